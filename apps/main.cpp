// contactlab — frictional contact between deformable solids, formulations and algorithms
// compared on the same model.
//
//   contactlab run [SCENE] [--out DIR] [--set key=value ...]
//   contactlab validate SCENE [--set key=value ...]
//   contactlab critical-mu SCENE [--out DIR] [--set key=value ...]
//   contactlab list
//   contactlab --version
#include "contactlab/Version.hpp"

#include "apps/RunCommand.hpp"
#include "apps/SceneSchema.hpp"

#include <Tpetra_Core.hpp>

#include <iostream>
#include <string>
#include <vector>

namespace {

const char* kUsage =
    "usage: contactlab <command> [options]\n"
    "\n"
    "commands:\n"
    "  run [SCENE] [--out DIR] [--set key=value ...]\n"
    "                      solve SCENE (a YAML file; without one, a small built-in scene) and\n"
    "                      write result.pvd, steps.csv and summary.json to DIR\n"
    "  validate SCENE [--set key=value ...]\n"
    "                      check SCENE and its mesh without solving\n"
    "  critical-mu SCENE [--out DIR] [--set key=value ...]\n"
    "                      run SCENE, then the critical friction coefficient of the last\n"
    "                      converged state's contact statuses (also in summary.json)\n"
    "  list                every registry with its parameters, defaults and doc strings\n"
    "  --version           print the version\n"
    "\n"
    "--set takes a '/'-separated key path, e.g. --set Mesh/rectangle/nx=20\n"
    "--set 'Linear Solver/Type=belos'\n";

int usageError(const std::string& message) {
  std::cerr << "contactlab: error: " << message << "\n\n" << kUsage;
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) return root ? usageError("no command given") : 2;
  const std::string command = args[0];

  if (command == "--version" || command == "version") {
    if (root) std::cout << "contactlab " << CONTACTLAB_VERSION << "\n";
    return 0;
  }
  if (command == "--help" || command == "-h" || command == "help") {
    if (root) std::cout << kUsage;
    return 0;
  }
  if (command == "list") {
    contactlab::registerAll();
    if (root) std::cout << "# contactlab scene reference\n\n" << contactlab::sceneReference();
    return 0;
  }
  if (command == "run" || command == "validate" || command == "critical-mu") {
    contactlab::RunOptions options;
    options.validateOnly = command == "validate";
    options.criticalMu = command == "critical-mu";
    for (std::size_t i = 1; i < args.size(); ++i) {
      const std::string& a = args[i];
      if ((a == "--out" || a == "--set") && i + 1 >= args.size())
        return root ? usageError(a + " needs a value") : 2;
      if (a == "--out")
        options.outputDirectory = args[++i];
      else if (a == "--set")
        options.overrides.push_back(args[++i]);
      else if (a.rfind("--", 0) == 0)
        return root ? usageError("unknown option '" + a + "'") : 2;
      else if (options.scenePath.empty())
        options.scenePath = a;
      else
        return root ? usageError("more than one scene given ('" + a + "')") : 2;
    }
    if ((options.validateOnly || options.criticalMu) && options.scenePath.empty())
      return root ? usageError(command + " needs a scene file") : 2;
    return contactlab::runCommand(options, comm);
  }
  return root ? usageError("unknown command '" + command + "'") : 2;
}
