// contactlab — frictional contact between deformable solids, formulations and algorithms
// compared on the same model.
//
//   contactlab run [SCENE] [--out DIR] [--set key=value ...]
//   contactlab run --restart DIR
//   contactlab validate SCENE [--set key=value ...]
//   contactlab critical-mu SCENE [--out DIR] [--set key=value ...]
//   contactlab study STUDY [--out DIR] [--retry-failed] [--no-plots]
//   contactlab batch [--quiet] < RUNS
//   contactlab list [AXIS]
//   contactlab --version
//   contactlab help [COMMAND], contactlab COMMAND --help
#include "contactlab/Version.hpp"

#include "apps/BatchCommand.hpp"
#include "apps/CommandErrors.hpp"
#include "apps/MpiSessionDirectory.hpp"
#include "apps/RunCommand.hpp"
#include "apps/SceneReference.hpp"
#include "base/InputError.hpp"
#include "core/io/Interruption.hpp"

#include <Tpetra_Core.hpp>
#include <mpi.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

const char* kUsage =
    "usage: contactlab <command> [options]\n"
    "\n"
    "commands:\n"
    "  run [SCENE] [--out DIR] [--set key=value ...] [--quiet], run --restart DIR\n"
    "                      solve SCENE (a YAML file; without one, a small built-in scene) and\n"
    "                      write result.pvd, steps.csv and summary.json to DIR\n"
    "  validate SCENE [--set key=value ...]\n"
    "                      check SCENE and its mesh without solving\n"
    "  critical-mu SCENE [--out DIR] [--set key=value ...]\n"
    "                      run SCENE, then the critical friction coefficient of the last\n"
    "                      converged state's contact statuses (also in summary.json)\n"
    "  study STUDY [--out DIR] [--retry-failed] [--no-plots]\n"
    "                      run a scene over the product of a study's axes (the runs in one\n"
    "                      batch process, each with a time limit; resumable), then study.csv,\n"
    "                      study.md and plots, and prints the comparison table (doc/studies.md)\n"
    "  batch [--quiet]     run the scenes listed on stdin one after another in this\n"
    "                      process (a line a run: OUT<tab>SCENE<tab>key=value...; what the\n"
    "                      study runner uses)\n"
    "  list [AXIS]         the scene's sections and every registry, with parameters, defaults\n"
    "                      and doc strings; AXIS: one of them (sections, mesh, material,\n"
    "                      element-technology, formulation, discretization, linear-solver)\n"
    "  --version           print the version\n"
    "  help [COMMAND]      this text, or a command's (also COMMAND --help)\n"
    "\n"
    "--set takes a '/'-separated key path, e.g. --set Mesh/rectangle/nx=20\n"
    "--set 'Linear Solver/Type=belos'\n";

// Per command: `contactlab help COMMAND`, `contactlab COMMAND --help`.
const char* commandHelp(const std::string& command) {
  if (command == "run")
    return "usage: contactlab run [SCENE] [--out DIR] [--set key/path=value ...] [--quiet]\n"
           "       contactlab run --restart DIR [--quiet]\n"
           "\n"
           "Solves SCENE (a YAML file; without one, a small built-in scene) and writes\n"
           "result.pvd (ParaView), steps.csv, contact.csv and summary.json to DIR (default: a\n"
           "folder named after the scene). --set overrides one scene key, e.g.\n"
           "  --set Mesh/rectangle/nx=20 --set 'Algorithm/Method=fixed-point'\n"
           "Exit code 0 converged, 1 a numerical failure (named in summary.json), 2 bad input,\n"
           "128 + signal when interrupted. Progress: a line per Newton iterate and per step on\n"
           "stderr (on a terminal, a live line with the ETA); --quiet drops it and the other\n"
           "informational lines (the model's size, automatic coefficients, removed files),\n"
           "keeping warnings, errors and the closing lines. The progress lines go to\n"
           "DIR/progress.log in any case (tail -f it to follow a quiet run). Scene keys:\n"
           "`contactlab list [AXIS]`, doc/scenes.md.\n"
           "A run writes DIR/checkpoint.h5 after each converged step (Output/Checkpoint Every).\n"
           "--restart DIR continues a killed run from it to the scene's End Time, appending to\n"
           "DIR's outputs (same scene and --set values required; a scene whose values changed\n"
           "is refused). A new run starts from it with the scene key Initial State: {From: DIR}.\n";
  if (command == "validate")
    return "usage: contactlab validate SCENE [--set key/path=value ...]\n"
           "\n"
           "Checks SCENE, its mesh and every parameter without solving; prints the model's\n"
           "size. Exit code 0 valid, 2 invalid (one sentence naming the key).\n";
  if (command == "critical-mu")
    return "usage: contactlab critical-mu SCENE [--out DIR] [--set key/path=value ...]\n"
           "\n"
           "Runs SCENE, then the critical friction coefficient of the last converged state's\n"
           "contact statuses: whether the solution is locally unique, and above which mu it\n"
           "may not be (summary.json 'critical_mu'; doc/algorithms.md, Uniqueness).\n";
  if (command == "study")
    return "usage: contactlab study STUDY [--out DIR] [--retry-failed] [--no-plots]\n"
           "\n"
           "Runs a scene over the product of a study's axes, each run with a time limit, in\n"
           "`contactlab batch` processes, as many runs at a time as the cores while the memory\n"
           "allows (a crash or a timeout ends only its run; the study keys Parallel Runs and\n"
           "Process Per Run change that); resumable. Writes study.csv, study.md and plots and\n"
           "prints the comparison table and where they are (doc/studies.md). `make run` runs\n"
           "scenes/studies/quick-comparison.yaml.\n";
  if (command == "batch")
    return "usage: contactlab batch [--quiet] < RUNS\n"
           "\n"
           "Runs scenes one after another in this process: one run a line on stdin,\n"
           "  OUT<tab>SCENE<tab>key/path=value<tab>...\n"
           "(SCENE empty: the built-in scene; the values as run --set takes them). Each run\n"
           "writes what `contactlab run SCENE --out OUT --set ...` writes, its output going to\n"
           "OUT/run.log, then prints 'exit CODE' (that command's exit code) on stdout. The\n"
           "start-up is paid once, a generated mesh is built once per Mesh section, and a run\n"
           "takes the linear solver the run before it left, with its factors: on the same\n"
           "mesh, a later run corrects them where its matrices differ instead of factorizing\n"
           "(the same results to the solver's tolerance). One rank. `contactlab study` runs\n"
           "its cases through it (doc/studies.md).\n";
  if (command == "list")
    return "usage: contactlab list [AXIS]\n"
           "\n"
           "Prints the scene's sections (geometry, loads, contact zones, algorithm, output...)\n"
           "and every registry (meshes, materials, element technologies, formulations,\n"
           "contact discretizations, linear solvers) with their parameters, defaults and doc\n"
           "strings, as in doc/scenes.md. AXIS prints one part: sections, mesh, material,\n"
           "element-technology, formulation, discretization or linear-solver.\n";
  return nullptr;
}

int usageError(const std::string& message) {
  std::cerr << "contactlab: error: " << message << "\n\n" << kUsage;
  return 2;
}

bool isHelp(const std::string& a) {
  return a == "--help" || a == "-h" || a == "help";
}

// What needs neither MPI nor Kokkos is answered before they start: help (Kokkos would print
// its own options first), the version and the reference (start-up costs about a second).
// Returns -1 when the command needs the parallel start-up.
int answerBeforeStartup(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) return usageError("no command given");
  const std::string& command = args[0];
  if (command == "--version" || command == "version") {
    std::cout << "contactlab " << CONTACTLAB_VERSION << "\n";
    return 0;
  }
  if (isHelp(command)) {
    if (args.size() == 1) {
      std::cout << kUsage;
      return 0;
    }
    const char* help = commandHelp(args[1]);
    if (!help) return usageError("no help for unknown command '" + args[1] + "'");
    std::cout << help;
    return 0;
  }
  const char* help = commandHelp(command);
  if (!help) return usageError("unknown command '" + command + "'");
  for (std::size_t i = 1; i < args.size(); ++i)
    if (args[i] == "--help" || args[i] == "-h") {
      std::cout << help;
      return 0;
    }
  if (command == "list") {
    if (args.size() > 2) return usageError("list takes one AXIS at most ('" + args[2] + "')");
    try {
      const std::string reference = contactlab::sceneReference(args.size() == 2 ? args[1] : "");
      std::cout << (args.size() == 2 ? "" : "# contactlab scene reference\n\n") << reference;
    } catch (const contactlab::InputError& e) {
      std::cerr << "contactlab: error: " << e.what() << "\n";
      return 2;
    }
    return 0;
  }
  return -1;  // run, validate, critical-mu, study, batch
}

// `contactlab study`: the study scripts start `contactlab batch` (or a `contactlab run` per
// case), so this process hands over before MPI starts (a forking MPI process is not portable).
int study(int argc, char** argv) {
  char self[4096];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) return usageError("cannot find the contactlab executable's path");
  self[n] = '\0';
  const std::string exe(self), bin = exe.substr(0, exe.rfind('/'));
  std::string script = bin + "/../" CONTACTLAB_STUDY_INSTALL_SUBDIR "/study.py";
  if (access(script.c_str(), R_OK) != 0) script = CONTACTLAB_STUDY_BUILD_DIR "/study.py";
  std::vector<std::string> words{"/usr/bin/python3", script, "--contactlab", exe};
  words.insert(words.end(), argv + 2, argv + argc);
  std::vector<char*> cargs;
  for (auto& w : words)
    cargs.push_back(w.data());
  cargs.push_back(nullptr);
  execv(cargs[0], cargs.data());
  std::cerr << "contactlab: error: cannot start " << words[0] << " " << script << ": "
            << std::strerror(errno) << "\n";
  return 1;
}

// run, validate, critical-mu or batch: answerBeforeStartup has answered every other command (and
// refused unknown ones) and `study` has handed over, before MPI started.
int dispatch(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int argc, char** argv) {
  const bool root = comm->getRank() == 0;
  const std::vector<std::string> args(argv + 1, argv + argc);
  const std::string& command = args[0];
  contactlab::installInterruptionHandlers();
  if (command == "batch") {
    bool quiet = false;
    for (std::size_t i = 1; i < args.size(); ++i) {
      if (args[i] != "--quiet" && args[i] != "-q")
        return root ? usageError("batch takes no argument but --quiet ('" + args[i] + "')") : 2;
      quiet = true;
    }
    return contactlab::batchCommand(comm, quiet);
  }
  contactlab::SimulationOptions options;
  options.validateOnly = command == "validate";
  options.criticalMu = command == "critical-mu";
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if ((a == "--out" || a == "--set" || a == "--restart") && i + 1 >= args.size())
      return root ? usageError(a + " needs a value") : 2;
    // An empty folder would be taken for none given (the scene's folder, or no restart).
    if ((a == "--out" || a == "--restart") && args[i + 1].empty())
      return root ? usageError(a + " needs a folder, not an empty value") : 2;
    if (a == "--quiet" || a == "-q")
      options.quiet = true;
    else if (a == "--out")
      options.outputDirectory = args[++i];
    else if (a == "--set")
      options.overrides.push_back(args[++i]);
    else if (a == "--restart" && command == "run")
      options.restartDirectory = args[++i];
    else if (a.rfind("--", 0) == 0)
      return root ? usageError("unknown option '" + a + "'") : 2;
    else if (options.scenePath.empty())
      options.scenePath = a;
    else
      return root ? usageError("more than one scene given ('" + a + "')") : 2;
  }
  if (!options.restartDirectory.empty() && !options.outputDirectory.empty())
    return root ? usageError("--restart DIR writes to DIR: --out does not go with it") : 2;
  if ((options.validateOnly || options.criticalMu) && options.scenePath.empty())
    return root ? usageError(command + " needs a scene file") : 2;
  return contactlab::runCommand(options, comm);
}

}  // namespace

int main(int argc, char** argv) {
  if (const int code = answerBeforeStartup(argc, argv); code != -1) return code;
  if (std::string(argv[1]) == "study") return study(argc, argv);
  // Started without mpirun, contactlab is an MPI singleton, for which Open MPI starts an orted
  // daemon beside it; the daemon serves only MPI_Comm_spawn, which contactlab does not use, and
  // cost 0.09 s of a 0.68 s run (patch-test-2d, median of 7). Isolated, the singleton starts
  // none. A user's own setting wins; under mpirun (OMPI_COMM_WORLD_SIZE) nothing changes.
  if (std::getenv("OMPI_COMM_WORLD_SIZE") == nullptr)
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  // Declared before the scope guard: removed after MPI_Finalize.
  contactlab::MpiSessionDirectory session;
  Tpetra::ScopeGuard scope(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  return contactlab::withErrorsReported(*comm, [&] { return dispatch(comm, argc, argv); });
}
