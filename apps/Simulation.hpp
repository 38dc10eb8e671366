#pragma once
// A run of a scene as an object: what `contactlab run`, `validate`, `critical-mu` and `batch`
// do, and what the Python module (python/) drives. Built from a scene (a file, YAML text in
// memory or the embedded default, with --set overrides), it owns the model, the contact problem,
// the linear solver, the state and the outputs (doc/scenes.md "The output folder"); step() and
// run() advance it, and each converged step's results are also kept in memory (history(),
// contactPoints(), displacement()).
#include "algorithms/StaticSolver.hpp"
#include "apps/Console.hpp"
#include "apps/RunCheckpoint.hpp"
#include "apps/SceneModel.hpp"
#include "base/LinearAlgebra.hpp"
#include "core/io/JsonWriter.hpp"
#include "formulations/ContactPointResult.hpp"

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace contactlab {

class ContactProblem;
class LinearSolver;
class LinearSolverPool;
class MeshCache;
class Problem;
struct NodalFields;
class RunOutputs;
class StaticRun;

struct SimulationOptions {
  std::string scenePath;               // empty: sceneText, or the embedded default scene
  std::string sceneText;               // a scene's YAML, when scenePath is empty
  std::string outputDirectory;         // empty: the scene's Output/Directory
  std::vector<std::string> overrides;  // --set key=value
  // Build and check only (`contactlab validate`): the output folder is not touched and the
  // simulation cannot step.
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

// A converged step as kept in memory (the steps.csv row's main columns).
struct StepResult {
  int step = 0;
  double time = 0;
  int iterations = 0;  // Newton iterations of the step, failed attempts included
  int cuts = 0;
  double residual = 0;
  ContactResultants contact;  // zero without contact
};

class Simulation {
 public:
  // Reads, validates and builds everything that can fail on bad input; nothing is written but
  // the output folder's preparation (removing an earlier run's files; not with validateOnly or a
  // restart). Collective. Throws InputError or LinearSolverError (same message on every rank).
  Simulation(const SimulationOptions& options, const Teuchos::RCP<const Comm>& comm);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // One converged load step (its outputs written), on the path of the uninterrupted run (one
  // StaticRun goes on from step to step, slow dynamics' velocity included). Returns false,
  // doing nothing, once the run has ended (End Time reached, or failed: report() says why).
  // Collective.
  bool step();
  // The steps left, to End Time or the first failure. Collective.
  const RunReport& run();
  // Writes summary.json and the closing lines (also after a failure), with the critical
  // friction coefficient for `criticalMu`. Returns the exit code `contactlab run` gives:
  // 0 converged, 1 failed numerically (or "stopped": finished before End Time), 128 + signal
  // when interrupted. Collective; once.
  int finish();

  bool ended() const { return ended_; }
  // The counts and the failure so far (converged once End Time is reached).
  const RunReport& report() const { return report_; }
  // The last converged step's load time (the start's before any).
  double time() const { return next_.time; }
  const std::vector<StepResult>& history() const { return history_; }
  // The last converged step's contact points (every zone; empty without contact).
  std::vector<ContactPointResult> contactPoints() const;
  // The last converged step's nodal displacements, dim per node, in the mesh's node order, on
  // rank 0 (empty on the others). Collective.
  std::vector<double> displacement() const;
  // The last converged step's nodal stresses and plastic strains (Problem::nodalFields), on
  // rank 0. Collective.
  NodalFields nodalFields() const;

  const SceneModel& scene() const { return sm_; }
  const Problem& problem() const { return *problem_; }
  const ContactProblem* contact() const { return contact_.get(); }
  const std::string& outputDirectory() const { return outDir_; }
  // The summary finish() wrote (null before).
  const JsonValue& summary() const { return summary_; }

  // Called with each Newton iterate (progress lines), on every rank. An exception it throws
  // leaves step() or run(), the simulation at its last converged step.
  void onIteration(std::function<void(const StaticSolver::IterateProgress&)> observer) {
    iterationObserver_ = std::move(observer);
  }

 private:
  void load();
  void build();
  void restoreStartingPoint();
  void resolveLinearSolver();
  void prepareOutputs();
  void advance(int maxSteps);
  void sayDroppedContact() const;
  double elapsed() const;

  struct SolverGiveBack;

  SimulationOptions options_;
  Teuchos::RCP<const Comm> comm_;
  bool root_;
  std::chrono::steady_clock::time_point start_;
  Console console_;
  SceneModel sm_;
  std::string scenePath_, hash_, outDir_;
  std::vector<std::string> overrides_;
  // The state the run starts from: at rest, or a checkpoint's (--restart, Initial State).
  std::string checkpoint_;
  bool restart_ = false;
  CheckpointInfo checkpointInfo_;
  RunStart next_;  // where the next step starts
  std::unique_ptr<Problem> problem_;
  std::unique_ptr<ContactProblem> contact_;
  std::unique_ptr<LinearSolver> solver_;
  std::unique_ptr<SolverGiveBack> giveBack_;
  Teuchos::RCP<Vector> x_;
  std::unique_ptr<RunOutputs> outputs_;
  std::unique_ptr<StaticRun> staticRun_;  // built at the first step
  double setupSeconds_ = 0;
  RunReport report_;
  std::vector<StepResult> history_;
  bool ended_ = false, finished_ = false;
  JsonValue summary_;
  std::function<void(const StaticSolver::IterateProgress&)> iterationObserver_;
};

}  // namespace contactlab
