#include "apps/Simulation.hpp"

#include "algorithms/RunStatic.hpp"
#include "algorithms/SlowDynamics.hpp"
#include "apps/Console.hpp"
#include "apps/DefaultScene.hpp"
#include "apps/LinearSolverPool.hpp"
#include "apps/output/CriticalMuSummary.hpp"
#include "apps/output/RunOutputs.hpp"
#include "base/InputError.hpp"
#include "base/NumberText.hpp"
#include "core/io/OutputFolder.hpp"
#include "core/problem/CollectiveError.hpp"
#include "core/problem/Problem.hpp"
#include "formulations/ContactProblem.hpp"
#include "linear/LinearSolverRegistry.hpp"

#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/resource.h>

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

// The settings that make two runs' solvers interchangeable: the Linear Solver section (after
// its Mode was resolved) and the communicator's size.
std::string solverKey(const Teuchos::ParameterList& scene, int ranks) {
  std::ostringstream key;
  scene.sublist("Linear Solver").print(key);
  return key.str() + "ranks " + std::to_string(ranks);
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
// technologies, no follower load) and the contact rows' (their laws, and the geometric terms
// the algorithm puts in the tangent).
bool tangentIsSymmetric(const SceneModel& sm, const Problem& problem,
                        const ContactProblem* contact) {
  const StaticSolverOptions& o = sm.solverOptions;
  const bool geometricTerms = o.geometryInNewton && o.geometricTerms != GeometricTerms::none;
  return problem.tangentSymmetric() && (!contact || contact->tangentSymmetric(geometricTerms));
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

// An InputError whose message names `where` (the scene's path) once.
InputError namedInputError(const std::string& where, const InputError& e) {
  const std::string message = e.what();
  if (message.find(where) != std::string::npos) return e;
  return InputError(where + ": " + message);
}

}  // namespace

// Gives the run's linear solver back to the pool (SimulationOptions::solverPool) when the
// simulation ends, unless an exception is leaving it: a solver interrupted inside its own work
// is dropped.
struct Simulation::SolverGiveBack {
  SolverGiveBack(LinearSolverPool* pool, std::unique_ptr<LinearSolver>& solver)
      : pool(pool), solver(solver), exceptions(std::uncaught_exceptions()) {}
  ~SolverGiveBack() {
    // A solver that dropped its symmetry for the run's geometry retry (takeAnyMatrix) no
    // longer answers to its key: a later run with these settings builds its own.
    if (pool && !key.empty() && std::uncaught_exceptions() == exceptions && solver &&
        solver->symmetryAssumption() == assumption)
      pool->giveBack(key, std::move(solver));
  }
  LinearSolverPool* pool;
  std::unique_ptr<LinearSolver>& solver;
  int exceptions;
  std::string key;         // the solver's settings (solverKey); empty without a pool
  std::string assumption;  // the solver's symmetryAssumption() when the run took it
};

Simulation::Simulation(const SimulationOptions& options, const Teuchos::RCP<const Comm>& comm)
    : options_(options),
      comm_(comm),
      root_(comm->getRank() == 0),
      start_(std::chrono::steady_clock::now()),
      console_(options.quiet, root_) {
  load();
  build();
  restoreStartingPoint();
  resolveLinearSolver();
  if (options_.validateOnly) return;
  outDir_ = restart_                           ? options_.restartDirectory
            : options_.outputDirectory.empty() ? sm_.outputDirectory
                                               : options_.outputDirectory;
  if (!restart_) {
    // Before solving: a folder that cannot be written is found now, not after step 1.
    collectively(*comm_, [&] {
      if (!root_) return;
      const std::vector<std::string> stale = prepareOutputFolder(outDir_);
      if (!stale.empty())
        console_.info(outDir_ + ": removed " + std::to_string(stale.size()) +
                      " file(s) of an earlier run");
    });
  }
  setupSeconds_ = elapsed();
  prepareOutputs();
}

Simulation::~Simulation() = default;

double Simulation::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

// The scene, with --restart's scene and overrides; the checkpoint an Initial State names.
void Simulation::load() {
  overrides_ = options_.overrides;
  scenePath_ = options_.scenePath;
  if (!options_.restartDirectory.empty()) {
    // --restart: the scene and overrides the checkpoint was written with.
    restart_ = true;
    checkpoint_ = checkpointPath(options_.restartDirectory);
    try {
      checkpointInfo_ = readCheckpointInfo(checkpoint_);
    } catch (const InputError& e) {
      throw InputError("--restart " + options_.restartDirectory + ": " + e.what());
    }
    if (scenePath_.empty()) scenePath_ = checkpointInfo_.scenePath;
    overrides_ = checkpointInfo_.overrides;
    overrides_.insert(overrides_.end(), options_.overrides.begin(), options_.overrides.end());
  }
  SceneFile file = !scenePath_.empty() ? readSceneFile(scenePath_, overrides_)
                   : !options_.sceneText.empty()
                       ? readSceneText(options_.sceneText, "<scene>", overrides_)
                       : readSceneText(kDefaultScene, "<default scene>", overrides_);
  sm_ = loadScene(std::move(file), comm_, options_.meshCache);
  hash_ = sceneHash(*sm_.scene.params);
  if (restart_ && hash_ != checkpointInfo_.sceneHash)
    throw InputError("--restart " + options_.restartDirectory + ": the scene " + sm_.scene.path +
                     " (with the checkpoint's --set overrides) is not the one the checkpoint "
                     "was written with (some value changed); --restart continues the same "
                     "run. To go on with other settings, start a new run from the checkpoint: "
                     "Initial State: {From: " +
                     options_.restartDirectory + "}");
  if (!restart_ && !sm_.initialStateFrom.empty()) {
    checkpoint_ = checkpointPath(sm_.initialStateFrom);
    try {
      checkpointInfo_ = readCheckpointInfo(checkpoint_);
    } catch (const InputError& e) {
      throw InputError(sm_.scene.path + ": Initial State/From: " + e.what());
    }
  }
  for (const std::string& sentence : sm_.notes)
    console_.info(sentence);
  for (const std::string& sentence : sm_.advice)
    console_.warning(sentence);
}

// The solid, the contact problem (paired in the initial state) and the regularization's mass.
void Simulation::build() {
  try {
    problem_ = std::make_unique<Problem>(sm_.model, comm_);
  } catch (const InputError& e) {
    throw namedInputError(sm_.scene.path, e);
  }
  if (root_) reportElementTechnologies(*problem_);
  if (!sm_.contact.empty()) {
    try {
      contact_ = std::make_unique<ContactProblem>(*problem_, sm_.contact);
      // Pairs the surfaces in the initial state: an initial penetration deeper than an element
      // is refused here, before anything runs (same verdict on every rank).
      auto x0 = contact_->createVector();
      contact_->updateGeometry(*x0, 0.0);
    } catch (const InputError& e) {
      throw InputError(sm_.scene.path + ": Contact: " + e.what());
    }
  }
  // The regularization's mass is checked now, not at the first step.
  try {
    SlowDynamics(sm_.solverOptions.slowDynamics).requireMass(*problem_);
  } catch (const InputError& e) {
    throw InputError(sm_.scene.path + ": Algorithm: " + e.what());
  }
  NonlinearSystem& system = contact_ ? static_cast<NonlinearSystem&>(*contact_) : *problem_;
  x_ = system.createVector();
}

// The state the run starts from: refused now if it is not this model's.
void Simulation::restoreStartingPoint() {
  next_.time = 0;
  if (checkpoint_.empty()) return;
  const bool continueTime = restart_ || sm_.initialStateContinuesTime;
  const std::string what =
      restart_ ? "--restart " + options_.restartDirectory : sm_.scene.path + ": Initial State/From";
  StepContinuation last;
  try {
    checkpointInfo_ =
        restoreCheckpoint(checkpoint_, *problem_, contact_.get(), *x_, continueTime, &last);
  } catch (const InputError& e) {
    throw InputError(what + ": " + checkpoint_ + ": " + e.what());
  }
  next_.fromState = true;
  if (continueTime) {
    // The same time line as the run that wrote it: its next step starts as it would have.
    next_.time = checkpointInfo_.time;
    next_.step = checkpointInfo_.step;
    next_.continuation = last;
    next_.loadReference = checkpointInfo_.loadReference;
    if (restart_) {  // the same run: its cut step size and its counts go on
      next_.stepSize = checkpointInfo_.stepSize;
      next_.totals = checkpointInfo_.totals;
    }
  }
  if (next_.time >= sm_.solverOptions.endTime * (1 - 1e-12))
    throw InputError(what + ": the checkpoint is at t = " + numberText(checkpointInfo_.time) +
                     ", not before Load Steps/End Time = " + numberText(sm_.solverOptions.endTime) +
                     ": nothing to run");
}

// The linear solver in the mode the tangent allows, and the checks that need it.
void Simulation::resolveLinearSolver() {
  // MUMPS' Mode 'automatic' (the default): LDL^T with 2x2 pivots on a symmetric tangent, about
  // 1.8x faster than LU on a 3D Hertz model of 125 571 dofs (doc/performance.md), LU otherwise.
  resolveAutomaticMode(sm_.scene.params->sublist("Linear Solver"),
                       tangentIsSymmetric(sm_, *problem_, contact_.get()));
  giveBack_ = std::make_unique<SolverGiveBack>(options_.solverPool, solver_);
  if (options_.solverPool) {
    giveBack_->key = solverKey(*sm_.scene.params, comm_->getSize());
    solver_ = options_.solverPool->take(giveBack_->key);
  }
  if (!solver_) solver_ = buildLinearSolver(*sm_.scene.params, comm_);
  giveBack_->assumption = solver_->symmetryAssumption();
  checkSymmetry(*problem_, *solver_, sm_.scene.path);
  // The uniqueness checks need the solver's determinants: a solver without them is refused now,
  // not after the run.
  if (contact_ && sm_.criticalMuCheck) requireDeterminantSolver(sm_, "Output/Critical Mu Check");
  if (contact_ && options_.criticalMu && hasFriction(sm_))
    requireDeterminantSolver(sm_, "critical-mu");
}

void Simulation::prepareOutputs() {
  const int steps = sm_.solverOptions.requestedSteps();
  const long long multipliers = contact_ ? static_cast<long long>(contact_->numMultipliers()) : 0;
  console_.info(sm_.scene.name + ": " + std::to_string(problem_->dofs().numGlobalDofs()) + " dofs" +
                (multipliers ? " + " + std::to_string(multipliers) + " multipliers" : "") + " on " +
                std::to_string(comm_->getSize()) + " rank(s), " + std::to_string(steps) +
                " load step(s)");
  OutputStart start;
  start.restart = restart_;
  start.fromState = next_.fromState;
  start.time = next_.time;
  start.stepsRows = checkpointInfo_.stepsRows;
  start.vtkFrames = checkpointInfo_.vtkFrames;
  start.requestedSteps = steps;
  start.checkpoint.scenePath =
      scenePath_.empty() ? "" : std::filesystem::absolute(scenePath_).lexically_normal().string();
  start.checkpoint.overrides = overrides_;
  start.checkpoint.sceneHash = hash_;
  outputs_ = std::make_unique<RunOutputs>(sm_, *problem_, contact_.get(), *solver_, comm_, console_,
                                          outDir_, start, *x_);
}

bool Simulation::step() {
  const int before = report_.steps;
  if (!ended_ && outputs_) advance(1);
  return report_.steps > before;
}

const RunReport& Simulation::run() {
  if (!ended_ && outputs_) advance(0);
  return report_;
}

void Simulation::advance(int maxSteps) {
  NonlinearSystem& system = contact_ ? static_cast<NonlinearSystem&>(*contact_) : *problem_;
  RunStart start = next_;
  start.maxSteps = maxSteps;
  // One StaticRun for the whole simulation: each call after the first goes on with its state.
  start.resume = staticRun_ != nullptr;
  if (!staticRun_)
    staticRun_ = std::make_unique<StaticRun>(system, contact_.get(), *solver_, sm_.solverOptions);
  auto onStep = [&](const StepReport& s, const Vector& state) {
    StepResult result;
    if (contact_) result.contact = contact_->resultants();
    outputs_->step(s, state, result.contact, elapsed());
    result.step = s.step;
    result.time = s.time;
    result.iterations = s.iterations;
    result.cuts = s.cuts;
    result.residual = s.residual;
    history_.push_back(result);
    // Where the next step starts: as the uninterrupted run would go on (a restart's start).
    next_.time = s.time;
    next_.step = s.step;
    next_.stepSize = s.nextStepSize;
    next_.fromState = true;
    next_.totals = s.run;
    next_.continuation = s.continuation;
    next_.loadReference = s.loadReference;
  };
  auto onIteration = [&](const StaticSolver::IterateProgress& p) {
    outputs_->iteration(p, elapsed());
    if (iterationObserver_) iterationObserver_(p);
  };
  RunReport r;
  try {
    r = staticRun_->run(*x_, onStep, onIteration, start);
  } catch (...) {
    // An observer's exception (a Python callback's) leaves the simulation at its last
    // converged step, which the next call starts from.
    report_.startFrom(next_.totals);
    report_.steps = static_cast<int>(history_.size());
    throw;
  }
  // Each call counts its own seconds; the counts of the loops are the run's totals.
  PhaseSeconds seconds = report_.seconds;
  seconds.assembly += r.seconds.assembly;
  seconds.linearSolve += r.seconds.linearSolve;
  seconds.output += r.seconds.output;
  report_ = r;
  report_.steps = static_cast<int>(history_.size());
  report_.seconds = seconds;
  ended_ = !r.paused;
}

// Said once per run: where the Dirichlet conditions fix a friction direction, its multiplier
// was dropped, and where they hold a node and its master in every direction, the point was
// opened (the singular tangent that would otherwise stop every algorithm there).
void Simulation::sayDroppedContact() const {
  if (!contact_) return;
  for (std::size_t z = 0; z < sm_.contact.size(); ++z) {
    const auto say = [&](const std::vector<std::int64_t>& nodes, const std::string& what) {
      if (!nodes.empty())
        console_.info("Contact/" + sm_.contact[z].name + ": at " + std::to_string(nodes.size()) +
                      " slave node(s) (e.g. node " +
                      std::to_string(sm_.model.mesh->nodeId(nodes.front())) + ") " + what);
    };
    say(contact_->prescribedSlipNodes(z),
        "the Dirichlet conditions fix a friction direction: its friction multiplier is dropped "
        "(the support carries that force)");
    say(contact_->prescribedGapNodes(z),
        "the node and its master are held by the Dirichlet conditions in every direction: "
        "their contact is left open (the supports carry that force)");
  }
}

int Simulation::finish() {
  if (finished_ || !outputs_)
    throw std::logic_error(
        "Simulation::finish: called twice, or "
        "on a simulation built to validate");
  finished_ = true;
  RunReport report = report_;
  if (!ended_) {  // stepped, then finished before its end: said as such, not as a success
    report.failure = "stopped";
    report.message = "finished at t = " + numberText(next_.time) +
                     " before Load Steps/End Time = " + numberText(sm_.solverOptions.endTime) +
                     " (the simulation was stepped and not run to its end)";
  }
  // A geometry retry made a symmetric-mode solver take any matrix (LinearSolver::takeAnyMatrix):
  // summary.json reports the mode the run ended in.
  if (!giveBack_->assumption.empty() && solver_->symmetryAssumption().empty())
    recordGeneralMode(sm_.scene.params->sublist("Linear Solver"));
  // summary.json and the last line count the whole run, its part before a restart too: the
  // solver's counts start from the checkpoint's (RunStart::totals), its steps are this run's.
  if (restart_) report.steps += static_cast<int>(checkpointInfo_.stepsRows);
  sayDroppedContact();
  outputs_->warnAfterRun(report);
  // Uniqueness: the critical friction coefficient of the last converged state's pattern.
  RunRecord record;
  if (options_.criticalMu) {
    record.criticalMu = JsonValue();
    if (!report.interruptSignal)
      record.criticalMu =
          criticalMuSummary(sm_, contact_.get(), *x_, next_.time, report.steps, comm_, console_);
  }
  // The summary, also when the run failed (the last converged step stays written).
  const double localMemory = peakMemoryMB();
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, 1, &localMemory, &record.peakMemoryMB);
  const MaterialStateSummary materialState = problem_->materialState();  // collective
  record.setupSeconds = setupSeconds_;
  // A run that did not converge with a user's coefficients far from the model's scale: say
  // which to change and to what (ContactScale.hpp: coefficientAdvice).
  if (!report.converged && (report.failure == "max-iterations" || report.failure == "diverged" ||
                            report.failure == "step-too-small"))
    for (const ContactZone& zone : sm_.contact)
      if (!zone.coefficientAdvice.empty()) report.message += "; " + zone.coefficientAdvice;
  summary_ = outputs_->finish(report, record, materialState, elapsed());
  if (report.interruptSignal) return 128 + report.interruptSignal;
  return report.converged ? 0 : 1;
}

std::vector<ContactPointResult> Simulation::contactPoints() const {
  return contact_ ? contact_->results() : std::vector<ContactPointResult>{};
}

std::vector<double> Simulation::displacement() const {
  return problem_->gatherDisplacements(contact_ ? *contact_->displacement(*x_) : *x_);
}

NodalFields Simulation::nodalFields() const {
  return problem_->nodalFields(contact_ ? *contact_->displacement(*x_) : *x_, next_.time);
}

}  // namespace contactlab
