#pragma once
// `contactlab run`: solves a scene and writes the results contract (doc/scenes.md "The output
// folder"): result.pvd + .vtu/.pvtu per converged step, steps.csv, summary.json.
#include "base/LinearAlgebra.hpp"

#include <string>
#include <vector>

namespace contactlab {

class LinearSolverPool;
class MeshCache;

struct RunOptions {
  std::string scenePath;               // empty: the embedded default scene
  std::string outputDirectory;         // empty: the scene's Output/Directory
  std::vector<std::string> overrides;  // --set key=value
  bool validateOnly = false;
  // `contactlab critical-mu`: after the run, the critical friction coefficient of the last
  // converged state's status pattern (printed and in summary.json under critical_mu).
  bool criticalMu = false;
  // --quiet: no progress or informational lines (Console.hpp); warnings, errors and the
  // command's answer (the closing lines, where the results are), still.
  bool quiet = false;
  // --restart DIR: continue the run whose outputs are in DIR from its checkpoint.h5 to the
  // scene's End Time, appending to its outputs. The scene and --set overrides are the
  // checkpoint's (scenePath, when given, replaces the path); a scene whose validated values
  // changed is refused (RunCheckpoint.hpp: sceneHash).
  std::string restartDirectory;
  // Where the run takes its linear solver from and gives it back to (`contactlab batch`):
  // null, a solver of its own.
  LinearSolverPool* solverPool = nullptr;
  // Where the run takes a generated mesh from and keeps it (`contactlab batch`); null: built.
  MeshCache* meshCache = nullptr;
};

// Returns the process exit code: 0 converged, 1 the run failed numerically (summary.json says
// why), 2 bad input (nothing written).
int runCommand(const RunOptions& options, const Teuchos::RCP<const Comm>& comm);

}  // namespace contactlab
