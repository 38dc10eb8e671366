#pragma once
// `contactlab run`, `validate` and `critical-mu`: a Simulation (Simulation.hpp) run to its end
// with the results contract written (doc/scenes.md "The output folder"): result.pvd + .vtu/.pvtu
// per converged step, steps.csv, summary.json.
#include "apps/Simulation.hpp"

namespace contactlab {

// Returns the process exit code: 0 converged (or valid), 1 the run failed numerically
// (summary.json says why), 2 bad input (nothing written), 128 + signal when interrupted.
int runCommand(const SimulationOptions& options, const Teuchos::RCP<const Comm>& comm);

}  // namespace contactlab
