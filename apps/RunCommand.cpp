#include "apps/RunCommand.hpp"

#include "apps/Console.hpp"
#include "base/InputError.hpp"
#include "core/problem/Problem.hpp"
#include "linear/LinearSolver.hpp"

#include <iostream>
#include <memory>

namespace contactlab {

int runCommand(const SimulationOptions& options, const Teuchos::RCP<const Comm>& comm) {
  const bool root = comm->getRank() == 0;
  std::unique_ptr<Simulation> simulation;
  // Bad input: one sentence on stderr, exit code 2, nothing written.
  auto reportInputError = [&](const std::exception& e) {
    if (root) std::cerr << "contactlab: error: " << e.what() << "\n";
    return 2;
  };
  try {
    simulation = std::make_unique<Simulation>(options, comm);
  } catch (const InputError& e) {
    return reportInputError(e);
  } catch (const LinearSolverError& e) {
    return reportInputError(e);
  }
  if (options.validateOnly) {
    const Mesh& mesh = *simulation->scene().model.mesh;
    Console(options.quiet, root)
        .result(simulation->scene().scene.path + ": valid (" + std::to_string(mesh.numNodes()) +
                " nodes, " + std::to_string(mesh.numElements()) + " elements)");
    return 0;
  }
  simulation->run();
  return simulation->finish();
}

}  // namespace contactlab
