#include "apps/RunCommand.hpp"

#include "algorithms/RunStatic.hpp"
#include "algorithms/SlowDynamics.hpp"
#include "apps/Console.hpp"
#include "apps/DefaultScene.hpp"
#include "apps/LinearSolverPool.hpp"
#include "apps/RunCheckpoint.hpp"
#include "apps/RunProgress.hpp"
#include "apps/SceneModel.hpp"
#include "apps/output/ContactCsv.hpp"
#include "apps/output/CriticalMuSummary.hpp"
#include "apps/output/ProbeValues.hpp"
#include "apps/output/ProfileCsv.hpp"
#include "apps/output/StepUniquenessCheck.hpp"
#include "apps/output/StepsCsv.hpp"
#include "apps/output/SummaryJson.hpp"
#include "apps/output/VtkSteps.hpp"
#include "base/InputError.hpp"
#include "base/NumberText.hpp"
#include "core/io/OutputFolder.hpp"
#include "core/io/OutputManifest.hpp"
#include "core/problem/CollectiveError.hpp"
#include "core/problem/Problem.hpp"
#include "formulations/ContactProblem.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <sys/resource.h>
#include <unistd.h>

namespace contactlab {
namespace {

// The process's resident-set high-water mark (VmHWM), which `contactlab batch` resets before
// each run (resetPeakMemory) so that each run reports its own; getrusage's maximum where /proc
// is not readable.
double peakMemoryMB() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // Linux reports kB
}

// Gives the run's linear solver back to the pool (RunOptions::solverPool) when the run ends,
// unless an exception is leaving the run: a solver interrupted inside its own work is dropped.
class SolverGiveBack {
 public:
  SolverGiveBack(LinearSolverPool* pool, std::unique_ptr<LinearSolver>& solver)
      : pool_(pool), solver_(solver), exceptions_(std::uncaught_exceptions()) {}
  SolverGiveBack(const SolverGiveBack&) = delete;
  SolverGiveBack& operator=(const SolverGiveBack&) = delete;
  ~SolverGiveBack() {
    // A solver that dropped its symmetry for the run's geometry retry (takeAnyMatrix) no
    // longer answers to its key: a later run with these settings builds its own.
    if (pool_ && !key.empty() && std::uncaught_exceptions() == exceptions_ && solver_ &&
        solver_->symmetryAssumption() == assumption)
      pool_->giveBack(key, std::move(solver_));
  }
  std::string key;         // the solver's settings (solverKey); empty without a pool
  std::string assumption;  // the solver's symmetryAssumption() when the run took it

 private:
  LinearSolverPool* pool_;
  std::unique_ptr<LinearSolver>& solver_;
  int exceptions_;
};

// The settings that make two runs' solvers interchangeable: the Linear Solver section (after
// its Mode was resolved) and the communicator's size.
std::string solverKey(const Teuchos::ParameterList& scene, int ranks) {
  std::ostringstream key;
  scene.sublist("Linear Solver").print(key);
  return key.str() + "ranks " + std::to_string(ranks);
}

// Bad input: one sentence on stderr, exit code 2.
int reportInputError(const std::exception& e, bool root) {
  if (root) std::cerr << "contactlab: error: " << e.what() << "\n";
  return 2;
}

// A follower pressure's load stiffness is not symmetric: a solver that assumes symmetry would
// solve another system (MUMPS reads one triangle, CG loses its guarantees). Refused before
// anything runs, the same on every rank (both sides are).
void checkSymmetry(const Problem& problem, const LinearSolver& solver, const std::string& where) {
  const std::string assumption = solver.symmetryAssumption();
  if (problem.followerLoads().empty() || assumption.empty()) return;
  throw InputError(where + ": Linear Solver/" + solver.name() + ": " + assumption + ", but load '" +
                   problem.followerLoads().front() +
                   "' is a pressure that follows the deformation of a finite-strain body, and "
                   "its load stiffness makes the tangent not symmetric; use a setting that takes "
                   "any matrix, or Follower: false on the load (a dead pressure on the reference "
                   "facets)");
}

// Whether the assembled tangent is symmetric: the solid's (its materials and element
// technologies, no follower load), every
// contact law's for its friction, and no node-to-segment geometric terms (the geometry in
// Newton with Geometric Terms pairing or full differentiate the normal along one side only).
bool tangentIsSymmetric(const SceneModel& sm, const Problem& problem) {
  if (!problem.tangentSymmetric()) return false;
  const StaticSolverOptions& o = sm.solverOptions;
  const bool geometricTerms = o.geometryInNewton && o.geometricTerms != GeometricTerms::none;
  const int nt = sm.model.mesh->dim - 1;
  for (const ContactZone& zone : sm.contact) {
    if (!zone.law->symmetricJacobian(zone.friction > 0 ? nt : 0)) return false;
    if (geometricTerms && zone.discretization == Discretization::nodeToSegment) return false;
  }
  return true;
}

// What `automatic` chose where it changed something or could not: a line per such block.
void reportElementTechnologies(const Problem& problem) {
  for (const BlockTechnology& t : problem.elementTechnologies()) {
    if (t.requested != "automatic") continue;
    if (t.name != "full")
      std::cout << "contactlab: block '" << t.block << "': element technology " << t.name
                << " (automatic: " << t.reason << ")\n";
    else if (t.reason.find(", but ") != std::string::npos)
      std::cerr << "contactlab: block '" << t.block << "': full integration: " << t.reason << "\n";
  }
}

// MUMPS' Mode 'automatic' (the default): LDL^T with 2x2 pivots (SYM = 2) on a symmetric
// tangent, about 1.8x faster than LU on a 3D Hertz model of 125 571 dofs (doc/performance.md),
// LU otherwise. Written into the scene, so summary.json reports the mode used.
void resolveSolverMode(Teuchos::ParameterList& scene, bool symmetric) {
  Teuchos::ParameterList& section = scene.sublist("Linear Solver");
  if (section.get<std::string>("Type") != "mumps") return;
  Teuchos::ParameterList& mumps = section.sublist("mumps");
  if (mumps.get<std::string>("Mode", "automatic") != "automatic") return;
  mumps.set("Mode", symmetric ? "symmetric-indefinite" : "general");
}

// The run's state before its first step: at rest, or a checkpoint's (--restart, Initial State).
struct StartingPoint {
  std::string checkpoint;  // the file, empty: from rest
  bool restart = false;    // --restart: the same run, continued in its own folder
  CheckpointInfo info;     // the checkpoint's (after restoring)
  RunStart start;          // for the solver
};

// For the tests of restarts: CONTACTLAB_TEST_KILL_AFTER_STEP=k kills every rank with SIGKILL
// right after step k's outputs and checkpoint are written (a crash at a step boundary, which
// nothing can clean up after).
void killAfterStepForTests(int step, const Comm& comm) {
  const char* value = std::getenv("CONTACTLAB_TEST_KILL_AFTER_STEP");
  if (value == nullptr || std::atoi(value) != step) return;
  comm.barrier();
  std::raise(SIGKILL);
}

}  // namespace

int runCommand(const RunOptions& options, const Teuchos::RCP<const Comm>& comm) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(clock::now() - start).count(); };
  const bool root = comm->getRank() == 0;
  const Console console(options.quiet, root);

  // 1. Read, validate and build everything that can fail on bad input: nothing is written yet.
  SceneModel sm;
  StartingPoint from;
  std::string hash;
  std::vector<std::string> overrides = options.overrides;
  std::string scenePath = options.scenePath;
  Teuchos::RCP<Vector> x;
  std::unique_ptr<Problem> problem;
  std::unique_ptr<ContactProblem> contact;
  std::unique_ptr<LinearSolver> solver;
  SolverGiveBack giveBack(options.solverPool, solver);
  try {
    if (!options.restartDirectory.empty()) {
      // --restart: the scene and overrides the checkpoint was written with.
      from.restart = true;
      from.checkpoint = checkpointPath(options.restartDirectory);
      try {
        from.info = readCheckpointInfo(from.checkpoint);
      } catch (const InputError& e) {
        throw InputError("--restart " + options.restartDirectory + ": " + e.what());
      }
      if (scenePath.empty()) scenePath = from.info.scenePath;
      overrides = from.info.overrides;
      overrides.insert(overrides.end(), options.overrides.begin(), options.overrides.end());
    }
    SceneFile file = scenePath.empty() ? readSceneText(kDefaultScene, "<default scene>", overrides)
                                       : readSceneFile(scenePath, overrides);
    sm = loadScene(std::move(file), comm, options.meshCache);
    hash = sceneHash(*sm.scene.params);
    if (from.restart && hash != from.info.sceneHash)
      throw InputError("--restart " + options.restartDirectory + ": the scene " + sm.scene.path +
                       " (with the checkpoint's --set overrides) is not the one the checkpoint "
                       "was written with (some value changed); --restart continues the same "
                       "run. To go on with other settings, start a new run from the checkpoint: "
                       "Initial State: {From: " +
                       options.restartDirectory + "}");
    if (!from.restart && !sm.initialStateFrom.empty()) {
      from.checkpoint = checkpointPath(sm.initialStateFrom);
      try {
        from.info = readCheckpointInfo(from.checkpoint);
      } catch (const InputError& e) {
        throw InputError(sm.scene.path + ": Initial State/From: " + e.what());
      }
    }
    for (const std::string& sentence : sm.notes)
      console.info(sentence);
    for (const std::string& sentence : sm.advice)
      console.warning(sentence);
    try {
      problem = std::make_unique<Problem>(sm.model, comm);
    } catch (const InputError& e) {
      const std::string message = e.what();
      if (message.find(sm.scene.path) != std::string::npos) throw;
      throw InputError(sm.scene.path + ": " + message);
    }
    if (root) reportElementTechnologies(*problem);
    if (!sm.contact.empty()) {
      try {
        contact = std::make_unique<ContactProblem>(*problem, sm.contact);
        // Pairs the surfaces in the initial state: an initial penetration deeper than an
        // element is refused here, before anything runs (same verdict on every rank).
        auto x0 = contact->createVector();
        contact->updateGeometry(*x0, 0.0);
      } catch (const InputError& e) {
        throw InputError(sm.scene.path + ": Contact: " + e.what());
      }
    }
    // The regularization's mass is checked now, not at the first step.
    try {
      SlowDynamics(sm.solverOptions.slowDynamics).requireMass(*problem);
    } catch (const InputError& e) {
      throw InputError(sm.scene.path + ": Algorithm: " + e.what());
    }
    if (!from.checkpoint.empty()) {
      // The state the run starts from: refused now if it is not this model's.
      NonlinearSystem& system = contact ? static_cast<NonlinearSystem&>(*contact) : *problem;
      x = system.createVector();
      const bool continueTime = from.restart || sm.initialStateContinuesTime;
      const std::string what = from.restart ? "--restart " + options.restartDirectory
                                            : sm.scene.path + ": Initial State/From";
      LastStep last;
      try {
        from.info =
            restoreCheckpoint(from.checkpoint, *problem, contact.get(), *x, continueTime, &last);
      } catch (const InputError& e) {
        throw InputError(what + ": " + from.checkpoint + ": " + e.what());
      }
      from.start.fromState = true;
      if (continueTime) {
        // The same time line as the run that wrote it: its next step starts as it would have.
        from.start.time = from.info.time;
        from.start.step = from.info.step;
        from.start.increment = last.increment;
        from.start.load = last.load;
        from.start.loadReference = from.info.loadReference;
        if (from.restart) {  // the same run: its cut step size and its counts go on
          from.start.stepSize = from.info.stepSize;
          from.start.totals = from.info.totals;
        }
      }
      if (from.start.time >= sm.solverOptions.endTime * (1 - 1e-12))
        throw InputError(what + ": the checkpoint is at t = " + numberText(from.info.time) +
                         ", not before Load Steps/End Time = " +
                         numberText(sm.solverOptions.endTime) + ": nothing to run");
    }
    resolveSolverMode(*sm.scene.params, tangentIsSymmetric(sm, *problem));
    if (options.solverPool) {
      giveBack.key = solverKey(*sm.scene.params, comm->getSize());
      solver = options.solverPool->take(giveBack.key);
    }
    if (!solver) solver = buildLinearSolver(*sm.scene.params, comm);
    giveBack.assumption = solver->symmetryAssumption();
    checkSymmetry(*problem, *solver, sm.scene.path);
    // The uniqueness checks need the solver's determinants: a solver without them is refused
    // now, not after the run.
    if (contact && sm.criticalMuCheck) requireDeterminantSolver(sm, "Output/Critical Mu Check");
    if (contact && options.criticalMu && hasFriction(sm))
      requireDeterminantSolver(sm, "critical-mu");
    if (options.validateOnly) {
      console.result(sm.scene.path + ": valid (" + std::to_string(sm.model.mesh->numNodes()) +
                     " nodes, " + std::to_string(sm.model.mesh->numElements()) + " elements)");
    } else if (!from.restart) {
      // Before solving: a folder that cannot be written is found now, not after step 1.
      const std::string folder =
          options.outputDirectory.empty() ? sm.outputDirectory : options.outputDirectory;
      collectively(*comm, [&] {
        if (!root) return;
        const std::vector<std::string> stale = prepareOutputFolder(folder);
        if (!stale.empty())
          console.info(folder + ": removed " + std::to_string(stale.size()) +
                       " file(s) of an earlier run");
      });
    }
  } catch (const InputError& e) {
    return reportInputError(e, root);
  } catch (const LinearSolverError& e) {
    return reportInputError(e, root);
  }
  if (options.validateOnly) return 0;
  const double setupSeconds = elapsed();

  const std::string outDir = from.restart                      ? options.restartDirectory
                             : options.outputDirectory.empty() ? sm.outputDirectory
                                                               : options.outputDirectory;
  const int steps = sm.solverOptions.requestedSteps();
  NonlinearSystem& system = contact ? static_cast<NonlinearSystem&>(*contact) : *problem;
  const long long multipliers = contact ? static_cast<long long>(contact->numMultipliers()) : 0;
  console.info(sm.scene.name + ": " + std::to_string(problem->dofs().numGlobalDofs()) + " dofs" +
               (multipliers ? " + " + std::to_string(multipliers) + " multipliers" : "") + " on " +
               std::to_string(comm->getSize()) + " rank(s), " + std::to_string(steps) +
               " load step(s)");

  // 2. Solve; each converged step is written at once.
  // Every file the run writes into outDir is listed first in the folder's manifest, which the
  // next run there reads to remove this one's files, and nothing else.
  OutputManifest folder(outDir, root);
  StepsCsv stepsCsv(folder, sm.criticalMuCheck && contact);
  ProbeValues probes(sm, *problem);
  const ProfileCsv profiles(sm, *problem);
  VtkSteps vtk(folder, rawMpiComm(comm));
  // The series starts from rest: a t = 0 frame before step 1 (also what a run that converges
  // no step leaves); a run from an earlier state starts from that state, at its time; a
  // continued run appends to its series.
  if (!x) x = system.createVector();
  try {
    if (from.restart) {
      // Continued: the series keep what was written up to the checkpoint, the rest is dropped.
      collectively(*comm, [&] {
        if (!root) return;
        prepareContinuedFolder(outDir);
        stepsCsv.resume(from.info.stepsRows);
      });
      if (sm.writeVtk)
        collectively(*comm, [&] { vtk.resume(static_cast<int>(from.info.vtkFrames)); });
    } else if (sm.writeVtk && from.start.fromState) {
      vtk.write(from.start.time, *problem, contact.get(),
                contact ? *contact->displacement(*x) : *x);
    } else if (sm.writeVtk) {
      vtk.writeRest(*problem, contact.get());
    }
  } catch (const InputError& e) {
    return reportInputError(e, root);
  }
  SummaryJson summary(sm, *problem, contact.get());
  // Output/Critical Mu Check: the uniqueness check after each converged step.
  std::unique_ptr<StepUniquenessCheck> uniqueness;
  if (sm.criticalMuCheck && contact)
    uniqueness = std::make_unique<StepUniquenessCheck>(sm, *contact, comm, console);
  RunProgress progress(root && !console.quiet(), sm.solverOptions.endTime,
                       root ? folder.path("progress.log") : "", from.restart);

  // The contact block of the last converged step: after a failure, the contact state left in
  // the problem is the failed iterate's, which summary.json reports under a key of its own.
  JsonValue convergedContact;
  double lastTime = from.start.time;
  // The checkpoint's bookkeeping: what this output series holds before this run's steps.
  CheckpointInfo checkpoint;
  checkpoint.scenePath =
      scenePath.empty() ? "" : std::filesystem::absolute(scenePath).lexically_normal().string();
  checkpoint.overrides = overrides;
  checkpoint.sceneHash = hash;
  const std::int64_t earlierRows = from.restart ? from.info.stepsRows : 0;
  int stepsThisRun = 0;
  std::vector<double> contactTimesWritten;
  auto onStep = [&](const StepReport& s, const Vector& state) {
    lastTime = s.time;
    // The displacement part of the system's unknowns (the whole vector without contact).
    auto solution =
        contact ? contact->displacement(state) : Teuchos::rcp(new Vector(state, Teuchos::Copy));
    if (sm.writeVtk) vtk.write(s.time, *problem, contact.get(), *solution);
    // The Output/Contact Times entry this step lands on, if any: its outputs are kept under
    // the time's name too.
    std::optional<double> stage;
    for (double t : sm.contactTimes)
      if (std::abs(s.time - t) <= 1e-9 * sm.solverOptions.endTime) stage = t;
    ContactResultants cr;
    if (contact) {
      cr = contact->resultants();
      if (root) ContactCsv(folder.path("contact.csv")).write(*contact, sm.contact, *sm.model.mesh);
      if (stage) {
        if (root)
          ContactCsv(folder.path("contact_t" + numberText(*stage) + ".csv"))
              .write(*contact, sm.contact, *sm.model.mesh);
        contactTimesWritten.push_back(*stage);
      }
      convergedContact = summary.contactBlock(cr).set("time", s.time);
    }
    // Read before the uniqueness check, whose assemblies count in the next step's timings.
    std::optional<ContactPhaseSeconds> contactSeconds;
    if (contact) contactSeconds = contact->phaseSeconds();
    const std::optional<double> condition = solver->conditionEstimate();
    std::optional<std::string> criticalMu;
    if (uniqueness) criticalMu = uniqueness->check(s, state);
    stepsCsv.addStep(s, cr, condition, contactSeconds, criticalMu);
    if (root) stepsCsv.write();
    probes.record(*solution, s.time);
    if (!sm.profiles.empty()) {
      profiles.write(folder, "", *solution, s.time);
      if (stage) profiles.write(folder, "_t" + numberText(*stage), *solution, s.time);
    }
    progress.step(s, steps, elapsed());
    // The checkpoint last: when it names a step, that step's outputs are all written.
    ++stepsThisRun;
    checkpoint.time = s.time;
    checkpoint.step = s.step;
    checkpoint.stepSize = s.nextStepSize;
    checkpoint.loadReference = s.loadReference;
    checkpoint.stepsRows = earlierRows + stepsThisRun;
    checkpoint.vtkFrames = vtk.frames();
    checkpoint.totals = s.run;
    const bool last = s.time >= sm.solverOptions.endTime;
    if (sm.checkpointEvery > 0 && (s.step % sm.checkpointEvery == 0 || last))
      writeCheckpoint(folder.path(kCheckpointFile), checkpoint, *problem, contact.get(), state,
                      {s.increment, s.load});
    killAfterStepForTests(s.step, *comm);
  };
  auto onIteration = [&](const StaticSolver::IterateProgress& p) {
    if (root) progress.iteration(p, elapsed());
  };
  RunReport report = runStatic(system, contact.get(), *solver, sm.solverOptions, *x, onStep,
                               onIteration, from.start);
  // A geometry retry made a symmetric-mode solver take any matrix (LinearSolver::takeAnyMatrix):
  // summary.json reports the mode the run ended in.
  if (!giveBack.assumption.empty() && solver->symmetryAssumption().empty()) {
    Teuchos::ParameterList& section = sm.scene.params->sublist("Linear Solver");
    if (section.get<std::string>("Type") == "mumps")
      section.sublist("mumps").set("Mode", "general");
  }
  // summary.json and the last line count the whole run, its part before a restart too: the
  // solver's counts start from the checkpoint's (RunStart::totals), its steps are this run's.
  report.steps += static_cast<int>(earlierRows);
  // Said once per run: where the Dirichlet conditions fix a friction direction, its multiplier
  // was dropped, and where they hold a node and its master in every direction, the point was
  // opened (the singular tangent that would otherwise stop every algorithm there).
  if (contact)
    for (std::size_t z = 0; z < sm.contact.size(); ++z) {
      const auto say = [&](const std::vector<std::int64_t>& nodes, const std::string& what) {
        if (!nodes.empty())
          console.info("Contact/" + sm.contact[z].name + ": at " + std::to_string(nodes.size()) +
                       " slave node(s) (e.g. node " +
                       std::to_string(sm.model.mesh->nodeId(nodes.front())) + ") " + what);
      };
      say(contact->prescribedSlipNodes(z),
          "the Dirichlet conditions fix a friction direction: its friction multiplier is dropped "
          "(the support carries that force)");
      say(contact->prescribedGapNodes(z),
          "the node and its master are held by the Dirichlet conditions in every direction: "
          "their contact is left open (the supports carry that force)");
    }
  // Output/Contact Times this run reached no converged step at (a continued run's earlier
  // part wrote its own).
  if (contact && report.converged)
    for (double t : sm.contactTimes)
      if (t > from.start.time && std::find(contactTimesWritten.begin(), contactTimesWritten.end(),
                                           t) == contactTimesWritten.end())
        console.warning("Output/Contact Times: no converged step at t = " + numberText(t) +
                        ": contact_t" + numberText(t) + ".csv was not written");
  // Only for a run that reached its end: a failed one may have failed where the surfaces met
  // (the seed-size tube under generalized Newton, at the joint's closing), and the warning
  // would send its user to check a geometry that is right.
  if (contact && report.converged && report.steps > 0 && !contact->everInContact())
    console.warning(
        "no contact point closed in any converged step: the contact surfaces never met (check "
        "the geometry, the loads and the search distance)");

  // Uniqueness: the critical friction coefficient of the last converged state's pattern.
  RunRecord record;
  if (options.criticalMu) {
    record.criticalMu = JsonValue();
    if (!report.interruptSignal)
      record.criticalMu =
          criticalMuSummary(sm, contact.get(), *x, lastTime, report.steps, comm, console);
  }

  // 3. Summary, also when the run failed (the last converged step stays written).
  const double localMemory = peakMemoryMB();
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 1, &localMemory, &record.peakMemoryMB);
  const MaterialStateSummary materialState = problem->materialState();  // collective
  if (root) {
    record.setupSeconds = setupSeconds;
    record.maxCondition = stepsCsv.maxConditionEstimate();
    record.convergedContact = convergedContact;
    record.probes = probes.json();
    record.resultPvd = vtk.pvdPath();
    if (uniqueness) record.possiblyNonUnique = uniqueness->possiblyNonUnique();
    record.totalSeconds = elapsed();
    const LinearSolverStats& work = solver->stats();
    record.linearWork =
        JsonValue::object()
            .set("analyses", work.analyses)
            .set("analysis_seconds", work.analysisSeconds)
            .set("factorizations", work.factorizations)
            .set("reused_factorizations", work.reusedFactorizations)
            .set("corrections", work.corrections)
            .set("single_precision_factorizations", work.singlePrecisionFactorizations)
            .set("refinement_steps", work.refinementSteps)
            .set("double_precision_fallbacks", work.doublePrecisionFallbacks)
            .set("factorization_seconds", work.factorizationSeconds)
            .set("correction_seconds", work.correctionSeconds)
            .set("solve_seconds", work.solveSeconds);
    // A run that did not converge with a user's coefficients far from the model's scale: say
    // which to change and to what (AutomaticAugmentation.hpp).
    if (!report.converged && (report.failure == "max-iterations" || report.failure == "diverged" ||
                              report.failure == "step-too-small"))
      for (const ContactZone& zone : sm.contact)
        if (!zone.coefficientAdvice.empty()) report.message += "; " + zone.coefficientAdvice;
    summary.build(report, record, materialState, comm->getSize())
        .write(folder.path("summary.json"));
    std::ostringstream closing;
    if (report.converged)
      closing << "contactlab: " << sm.scene.name << " converged in " << report.steps << " step(s), "
              << report.iterations << " Newton iterations, " << elapsed() << " s";
    else
      closing << "contactlab: " << sm.scene.name << " FAILED (" << report.failure
              << "): " << report.message;
    console.result(closing.str());
    progress.finish(closing.str());
    if (record.resultPvd)
      console.result("  results: " + std::filesystem::absolute(*record.resultPvd).string());
    console.result("  summary: " + std::filesystem::absolute(outDir + "/summary.json").string());
  }
  if (report.interruptSignal) return 128 + report.interruptSignal;
  return report.converged ? 0 : 1;
}

}  // namespace contactlab
