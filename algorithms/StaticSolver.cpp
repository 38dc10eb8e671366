#include "algorithms/StaticSolver.hpp"

#include "algorithms/AlgorithmPresets.hpp"
#include "algorithms/SolidAlonePredictor.hpp"
#include "base/Elapsed.hpp"
#include "base/NumberText.hpp"
#include "core/io/Interruption.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <optional>
#include <utility>

namespace contactlab {
namespace {

// Thrown from the Newton observer when a signal asked the run to stop (every rank at once).
struct Interrupted {
  int signal;
};

// A step whose start's residual is below this fraction of the last loaded step's holds the
// load (solveStep). A cut step's is about half its uncut one's; a held step's 1e-8 or less.
constexpr double kHeldLoadFraction = 1e-3;

}  // namespace

StaticSolver::~StaticSolver() = default;

StaticSolver::StaticSolver(NonlinearSystem& problem, ContactControls* controls,
                           NewtonMethod& newton, StaticSolverOptions options, LinearSolver* solver,
                           NewtonMethod* retry)
    : problem_(problem),
      controls_(controls),
      newton_(newton),
      retry_(retry),
      options_(std::move(options)),
      solver_(solver),
      detector_(options_.grazingTolerance),
      loops_(composeLoops(options_, problem, controls)),
      slowDynamics_(options_.slowDynamics),
      geometryInNewton_(options_.geometryInNewton) {
  slowDynamics_.requireMass(problem_);
  if (options_.lineSearchRetry == "never") retry_ = nullptr;
  if (controls_) controls_->setGeometricTerms(ownGeometricTerms());
}

GeometricTerms StaticSolver::ownGeometricTerms() const {
  return options_.geometryInNewton ? options_.geometricTerms : GeometricTerms::none;
}

StaticSolver::FullGeometricTerms::FullGeometricTerms(StaticSolver& solver) : solver_(solver) {
  solver.controls_->setGeometricTerms(GeometricTerms::full);
  // The full terms differentiate a node-to-segment normal along one side only: a solver that
  // took the tangent as symmetric takes any matrix from now on (MUMPS: LU).
  if (solver.solver_) solver.solver_->takeAnyMatrix();
}

StaticSolver::FullGeometricTerms::~FullGeometricTerms() {
  solver_.controls_->setGeometricTerms(solver_.ownGeometricTerms());
}

StaticSolver::GeometryInNewton::GeometryInNewton(StaticSolver& solver)
    : solver_(solver), terms_(solver) {
  StaticSolverOptions options = solver.options_;
  options.geometryInNewton = true;
  if (solver.geometryInNewtonLoops_.empty())
    solver.geometryInNewtonLoops_ = composeLoops(options, solver.problem_, solver.controls_);
  std::swap(solver.loops_, solver.geometryInNewtonLoops_);
  solver.geometryInNewton_ = true;
}

StaticSolver::GeometryInNewton::~GeometryInNewton() {
  std::swap(solver_.loops_, solver_.geometryInNewtonLoops_);
  solver_.geometryInNewton_ = false;
}

bool StaticSolver::fullTermsRetryApplies() const {
  return options_.geometryRetry && controls_ && options_.geometryInNewton &&
         options_.geometricTerms != GeometricTerms::full && controls_->fullTermsAddToPairing();
}

bool StaticSolver::geometryRetryApplies() const {
  return options_.geometryRetry && controls_ && !geometryInNewton_;
}

bool StaticSolver::statusLoopOutsideNewton() const {
  for (const auto& loop : loops_)
    if (loop->changesStatuses() && !loop->inNewton()) return true;
  return false;
}

int StaticSolver::treatCycling(const std::vector<CyclingEvent>& events, StepReport& sr) {
  int changed = 0;
  for (const CyclingEvent& e : events) {
    ++sr.cycling[static_cast<int>(e.kind)];
    controls_->markCycling(e.point, static_cast<int>(e.kind));
    if (!treating_ || untreated_ || options_.cyclingTreatment == "none") continue;
    const bool frictionCycle =
        e.kind == CyclingKind::StickSlip || e.kind == CyclingKind::SlipReversal;
    // 'combined': no coefficient breaks a friction cycle (in 2D the slip piece has no
    // tangential stiffness whatever r_t), so those are forced; a contact cycle has its
    // coefficients scaled, except with the geometry in Newton, where a scaled r_n also scales
    // the geometric terms and the cycles multiplied (Cattaneo-Mindlin, generalized Newton: 148
    // sub-cycling events and no convergence): forced there too (doc/algorithms.md, "Cycling").
    // And under a status fixed point, whose frozen statuses no coefficient changes: SSNV128's
    // fixed point cycled through 30 status updates (statuses-not-converged); forced, it
    // converges (hertz-2d-two-body 17 -> 18 iterations, cattaneo-mindlin-2d 66 -> 77).
    // 'automatic' with Lagrange: its constants only pick the status, so the Newton steps of a
    // cycle do not see them and scaling breaks nothing (pad-2d: 22 sub-cycling and 37
    // stick-slip events, |R| 9e6 at max-iterations, where the augmented Lagrangian converges in
    // 16): such a point is forced.
    const bool force =
        options_.cyclingTreatment == "forced" ||
        (options_.cyclingTreatment == "combined" &&
         (frictionCycle || geometryInNewton_ || statusLoopOutsideNewton())) ||
        (options_.cyclingTreatment == "automatic" && !controls_->scalingChangesForces(e.point));
    if (force) {
      forcedPoints_.push_back(e.point);
      stepForced_ = true;
      const int status = e.kind == CyclingKind::StickSlip      ? 2
                         : e.kind == CyclingKind::SlipReversal ? 1
                                                               : kForcedClosed;
      controls_->forceStatus(e.point, status);
      detector_.forget(e.point);
      ++changed;
    } else if (controls_->scaleCoefficients(e.point, 10.0)) {
      ++changed;
    }
  }
  return changed;
}

bool StaticSolver::forcedStateHolds(const Vector& x, double t, double target, Vector& residual) {
  if (forcedPoints_.empty() || !treating_) return true;
  treating_ = false;
  controls_->releaseForcedStatuses();
  // A fixed point whose frozen state the forcing set (a forced point's frozen status is the
  // forced one) takes it from the model's law again here.
  bool revised = false;
  for (const auto& loop : loops_)
    if (!loop->inNewton() && loop->reviseForcedState(x, t)) revised = true;
  problem_.assemble(x, t, &residual, false);
  // The contact equations as forces too (ContactControls::constraintResidual): a stick-slip
  // point forced to slip with a traction of 2.4 mu p (SSNV128 with lagrange) leaves its friction
  // row at w (|Lambda| - 1), a number far below a target in forces.
  forcedResidual_ = std::max(residual.norm2(), controls_->constraintResidual());
  return !revised && forcedResidual_ <= target;
}

bool StaticSolver::solveStep(NewtonMethod& newton, const Vector& u, Vector& x, StepReport& sr,
                             RunReport& report, const IterationCallback& onIteration,
                             double maxUpdate) {
  const double t = sr.time;
  x.assign(u);
  problem_.applyDirichlet(t, x);
  forcedPoints_.clear();
  treating_ = true;
  if (controls_) {
    controls_->releaseTreatments();
    detector_.reset();
  }
  for (const auto& loop : loops_)
    loop->beginStep();
  slowDynamics_.beginStep(problem_, t);
  problem_.updateGeometry(x, t);
  auto residual = problem_.createVector();
  const ExtrapolatedStart start = extrapolatedStart(u, x, t, *residual);
  const Prediction prediction = start.moved ? Prediction{} : predict(u, x, sr, report);
  if (prediction.done) problem_.updateGeometry(x, t);
  // The step's reference residual, and the statuses the fixed points start from: a predicted
  // step has its reference already, and without contact nothing else reads this assembly. An
  // extrapolated step keeps the plain start's: the tolerance stays relative to the increment's
  // load, not to how well the extrapolation guessed. Where the extrapolation assembled at x
  // and no predictor moved it since, that assembly stands.
  double reference = prediction.done ? prediction.residual : start.plainResidual;
  const bool assembledAtX = start.plainResidual >= 0 && !prediction.done;
  if (!assembledAtX && (!prediction.done || controls_)) {
    problem_.assemble(x, t, residual.get(), false);
    if (!prediction.done) reference = residual->norm2();
  }
  // A step that holds the load (a plateau of a time table, a stage that waits) starts from
  // what the last step left, ~1e-8 of that step's start or a geometry update's leftover, and
  // 1e-8 of that lies below the residual's round-off: a shrink fit in 3 steps asked 9e-13 of
  // its second step and stalled at 5e-10 until max-iterations. Such a step's reference is at
  // least kHeldLoadFraction of the last loaded step's: its neighbours' accuracy.
  if (reference < kHeldLoadFraction * loadReference_)
    reference = kHeldLoadFraction * loadReference_;
  else
    loadReference_ = reference;
  // What the step's residual is made small against: the larger of that reference and the forces
  // the model carries at the step's start (its loads and the reactions that balance them,
  // NonlinearSystem::internalForceNorm). 1e-8 of an increment can lie below the round-off of
  // those forces, and a cut shrinks the increment, not them: a plastic Cook's membrane at
  // nu = 0.4999 stalled at 1.8e-9 against a target of 3.2e-10 (1e-8 of its tenth increment).
  const double scale = std::max(reference, problem_.internalForceNorm());
  // The fixed points start from the statuses and thresholds of the predictor.
  for (const auto& loop : loops_)
    if (!loop->inNewton()) loop->freeze();

  const auto fail = [&](const std::string& failure, const std::string& message) {
    report.failure = failure;
    report.message =
        message + " at step " + std::to_string(sr.step) + " (t = " + scientificText(t) + ")";
    if (failure == kSingularTangent) report.message += singularTangentRemedy();
    if (!treating_ && !forcedPoints_.empty()) {
      // The forced treatment had converged on its modified law, and the model's own law
      // failed from there: name that, and the points.
      std::vector<std::size_t> points = forcedPoints_;
      std::sort(points.begin(), points.end());
      points.erase(std::unique(points.begin(), points.end()), points.end());
      std::string list;
      for (std::size_t i = 0; i < points.size() && i < 10; ++i)
        list += (i ? ", " : "") + std::to_string(points[i]);
      if (points.size() > 10) list += ", ...";
      report.failure = "degraded-contact";
      report.message =
          "the forced cycling treatment converged to a state that violates the "
          "contact law at its " +
          std::to_string(points.size()) + " forced point(s) (contact points " + list +
          "; |R| = " + scientificText(forcedResidual_) +
          " with the law restored), and Newton from there without the treatment "
          "failed (" +
          failure + ": " + report.message + ")";
    }
    return false;
  };
  if (!prediction.failure.empty()) return fail(prediction.failure, prediction.message);
  // A converged state whose contact lost slave nodes through its master is no solution
  // (ContactControls::passedThrough): the step fails, and its retries or a cut may pass.
  const auto accepted = [&]() {
    const std::string through = controls_ ? controls_->passedThrough(x) : std::string();
    return through.empty() ? true : fail("contact-passed-through", through);
  };
  // The solid-alone predictor where the tangent one does not start a contact model's step.
  const bool solidAlone = !prediction.done && controls_ && options_.statusesInNewton &&
                          (options_.predictor == "solid-alone" ||
                           (options_.predictor == "automatic" && u.normInf() == 0)) &&
                          reference > options_.absoluteTolerance && stepSolidAlone(x, t, sr);
  if (solidAlone) ++report.linearSolves;
  int solves = prediction.done || solidAlone ? 1 : 0;
  IterateProgress progress;
  progress.step = sr.step;
  progress.time = t;
  progress.attempt = attempt_;
  if (onIteration && (prediction.done || solidAlone)) {
    progress.residual = prediction.done ? prediction.residual : reference;
    onIteration(progress);
  }
  NewtonMethod::Observer observer;
  observer.treat = [&](int) {
    progress.treatedPoints =
        controls_ ? treatCycling(detector_.observe(controls_->pointStates()), sr) : 0;
    return progress.treatedPoints > 0;
  };
  observer.report = [&](int iteration, double norm) {
    if (const int signal = interruptionAgreed(mpiComm_)) throw Interrupted{signal};
    sr.residual = norm;
    progress.iteration = solves + iteration;
    progress.residual = norm;
    if (controls_) {
      progress.statusChanges = iteration == 0 ? 0 : controls_->statusChanges();
      progress.contactResidual = controls_->constraintResidual();
    }
    if (onIteration) onIteration(progress);
    progress.treatedPoints = 0;
    progress.restartedBy = "";
  };
  NewtonRequest request;
  request.time = t;
  request.target = std::max(options_.absoluteTolerance, options_.relativeTolerance * scale);
  request.maxIterations = &newton == retry_ ? options_.retryMaxIterations : options_.maxIterations;
  request.geometryInNewton = geometryInNewton_;
  request.maxUpdate = maxUpdate;
  request.stallIterations = maxUpdate > 0 ? 0 : options_.stallIterations;
  request.roundoffStop = true;
  progress.target = request.target;
  for (;;) {
    const NewtonOutcome outcome = newton.solve(x, request, observer);
    solves += outcome.iterations;
    sr.iterations += outcome.iterations;
    sr.residual = outcome.residual;
    sr.seconds.assembly += outcome.assemblySeconds;
    sr.seconds.linearSolve += outcome.linearSolveSeconds;
    report.linearSolves += outcome.iterations;
    report.limitedUpdates += outcome.limitedUpdates;
    report.unevaluableHalvings += outcome.unevaluableHalvings;
    report.roundoffStops += outcome.roundoffStops;
    sr.longestUpdate = std::max(sr.longestUpdate, outcome.longestUpdate);
    if (!outcome.failure.empty()) {
      // A NaN residual from an iterate the solid could not evaluate: say which and where.
      const AssemblyFailure assembly = problem_.assemblyFailure();
      if (!assembly.code.empty()) return fail(assembly.code, assembly.message);
      return fail(outcome.failure, outcome.message);
    }
    // The innermost fixed point whose update moves restarts Newton; the loops outside it are
    // not updated until it settles.
    std::size_t k = 0;
    while (k < loops_.size() && (loops_[k]->inNewton() || !loops_[k]->update(x, t)))
      ++k;
    if (k == loops_.size()) {
      // A solve allowed to stop short of the step's target (the forcing between fixed-point
      // updates, or the round-off floor) after which no fixed point moved: the step ends on a
      // solve to its own target (unless this one got there anyway). A floor stop is taken for
      // what the fixed points would do from it, not as a solution: the perfectly plastic tube
      // past its limit load stopped at its floor 100 times its size away.
      if ((request.forcing > 0 || request.roundoffStop) &&
          !newtonConverged(outcome.residual, request, controls_, 0)) {
        request.forcing = 0;
        request.roundoffStop = false;
        continue;
      }
      // A forced state that violates the model's law is not a solution: Newton goes on from
      // it with the law restored (near a solution, it converges in a few iterations).
      if (forcedStateHolds(x, t, request.target, *residual)) return accepted();
      continue;
    }
    // Counts loop `index`'s update that moved, within its cap (false: the cap was reached).
    const auto countUpdate = [&](std::size_t index) {
      FixedPointLoop& loop = *loops_[index];
      progress.restartedBy = loop.name().c_str();
      if (loop.updates() == loop.maxUpdates()) return false;
      loop.recordUpdate(sr);
      if (loop.renewsInnerCaps())
        for (std::size_t inner = 0; inner < index; ++inner)
          loops_[inner]->renewCap();
      return true;
    };
    FixedPointLoop& moved = *loops_[k];
    // A status that flips from one fixed-point update to the next cycles too.
    if (moved.changesStatuses()) treatCycling(detector_.observe(controls_->pointStates()), sr);
    if (!countUpdate(k)) return fail(moved.failure(), moved.failureMessage());
    // A loop that cycles at what the fixed point around it holds frozen lets that one update
    // too before Newton restarts (the dragged pad: a stale friction threshold, with which no
    // status of its point held). Not a farther one: the geometry re-pairs from any state.
    if (moved.cyclesAtFrozenSurroundings()) {
      std::size_t outer = k + 1;
      while (outer < loops_.size() && loops_[outer]->inNewton())
        ++outer;
      if (outer < loops_.size() && loops_[outer]->update(x, t) && !countUpdate(outer))
        return fail(loops_[outer]->failure(), loops_[outer]->failureMessage());
    }
    const FixedPointLoop::MovedStateTest test = moved.testMovedState(x, t, reference, *residual);
    if (test.tested) {
      sr.residual = test.residual;
      if (test.residual <= test.target && forcedStateHolds(x, t, test.target, *residual))
        return accepted();
    }
    // A fixed point that diverges is given up at once where the geometry retry takes it over:
    // its remaining updates would climb on (the NAFEMS roller: 25 more, 140 Newton iterations).
    if (geometryRetryApplies() && moved.diverged())
      return fail(moved.failure(), moved.failureMessage());
    // Inexact solves between fixed-point updates (doc/algorithms.md): the next update moves
    // the residual by a fraction of the last one's (5 to 10 times less, converging), so
    // solving below Fixed Point Forcing times it buys nothing.
    request.forcing = options_.fixedPointForcing;
    request.roundoffStop = true;
  }
}

namespace {
// Whether a step failed because its iterates did not settle or went where the system cannot be
// evaluated (an element inverted, a contact facet without a dual basis: NOX's backtracking
// rejects such a trial point and halves the step, UnevaluableIterate.NoxBacktracking...), which
// a line search may change; not a singular tangent.
bool iteratesFailedToConverge(const std::string& failure) {
  for (const char* name : {"max-iterations", "diverged", "degraded-contact",
                           "statuses-not-converged", "thresholds-not-converged",
                           "geometry-not-converged", "nan-detected", "contact-geometry-failed",
                           "contact-passed-through", "inverted-element", "material-update-failed"})
    if (failure == name) return true;
  return false;
}

// A step attempt's counts into the run's, converged or not.
void account(const StepReport& sr, RunReport& report) {
  report.iterations += sr.iterations;
  report.statusIterations += sr.statusIterations;
  report.thresholdIterations += sr.thresholdIterations;
  report.geometryIterations += sr.geometryIterations;
  for (int k = 0; k < kCyclingKinds; ++k)
    report.cycling[k] += sr.cycling[k];
  report.seconds.assembly += sr.seconds.assembly;
  report.seconds.linearSolve += sr.seconds.linearSolve;
}
}  // namespace

double StaticSolver::stepEnd(double t, double dt) const {
  // The end of t's nominal step (k End Time / Steps or an entry of Times), and the first
  // landing time before it:
  // after cuts and regrowth the steps drift off the nominal grid, and a step from t = 0.9375
  // to 1.1875 passed the peak of the hex27 tube's load table at t = 1 (Backtrack run: 297 N of
  // residual contact force where the steps that land on t = 1 give 358 N).
  const StaticSolverOptions::NominalStep nominal = options_.nominalStep(t);
  const double margin = 1e-9 * nominal.length;
  double stop = nominal.end;
  for (double landing : options_.landingTimes)
    if (landing > t + margin && landing < stop - margin) stop = landing;
  return t + dt > stop - margin ? stop : t + dt;
}

RunReport StaticSolver::run(Vector& u, const StepCallback& onStep,
                            const IterationCallback& onIteration, const RunStart& start) {
  RunReport report;
  report.startFrom(start.totals);
  mpiComm_ = rawMpiComm(u.getMap()->getComm());
  if (controls_ && !start.fromState) controls_->seedInitialStatuses(u, start.time);
  if (!start.resume) {
    const StepContinuation& c = start.continuation;
    if (c.increment && c.load) extrapolation_.restore(*c.increment, *c.load);
    slowDynamics_.start(u, start.time);
    if (c.slowDynamicsPrevious)
      slowDynamics_.restorePrevious(*c.slowDynamicsPrevious, c.slowDynamicsStep);
  }
  loadReference_ = start.loadReference;
  // However the run ends, what runs after it (outputs, diagnostics) sees the static system.
  struct StaticAfterRun {
    const SlowDynamics& slowDynamics;
    NonlinearSystem& system;
    ~StaticAfterRun() { slowDynamics.end(system); }
  } staticAfterRun{slowDynamics_, problem_};
  auto x = problem_.createVector();
  double t = start.time;
  double dt = start.stepSize > 0 ? start.stepSize : options_.nominalStep(t).length;
  int cuts = 0;  // in a row, for the current step
  const double updateLimit = options_.maxUpdate * problem_.modelSize();
  while (t < options_.endTime * (1 - 1e-12)) {
    StepReport sr;
    sr.step = start.step + report.steps + 1;
    sr.cuts = cuts;
    sr.time = stepEnd(t, dt);
    const double h = sr.time - t;  // dt, or less where the step lands on a time it must not pass
    const double nominal = options_.nominalStep(t).length;
    const double smallest = std::ldexp(nominal, -options_.maxCuts);
    // The floor: a run whose every step converges only after a cut would otherwise halve dt
    // without end and creep towards a time it never reaches (measured: the elasto-plastic
    // 3D ironing, 1e-5 steps at t = 0.8124 after an hour).
    const bool atFloor = h / 2 < smallest * (1 - 1e-9);
    const bool lastTry = cuts == options_.maxCuts || atFloor;
    bool ok = false;
    stepForced_ = false;
    try {
      ok = solveStep(newton_, u, *x, sr, report, onIteration);
      // A failed step solved again another way from its start (sr counts every attempt); a
      // failed second try reports the first attempt's failure (the one a table of methods
      // compares), the second's in its message.
      const auto solveAgain = [&](NewtonMethod& method, double maxUpdate, const char* attempt,
                                  const std::string& how) {
        const std::string failure = report.failure, message = report.message;
        attempt_ = attempt;
        const bool solved = solveStep(method, u, *x, sr, report, onIteration, maxUpdate);
        attempt_ = "";
        if (solved) {
          report.failure.clear();
          report.message.clear();
          return true;
        }
        report.message =
            message + "; solved again " + how + ": " + report.failure + ": " + report.message;
        report.failure = failure;
        return false;
      };
      // A geometric fixed point that diverged diverges again with a line search or a shorter
      // step: its frozen normal is the master's, which turns as the master dents (the NAFEMS
      // roller under its force). The consistent tangent converges there: the step is solved
      // again with the geometry in Newton and its full terms (doc/algorithms.md "Geometry
      // retry").
      // The retries after it, if it fails, keep the geometry in Newton.
      std::optional<GeometryInNewton> geometryInNewton;
      if (!ok && geometryRetryApplies() && report.failure == "geometry-not-converged" &&
          loops_.back()->diverged()) {
        ++report.geometryRetries;
        geometryInNewton.emplace(*this);
        ok = sr.geometryRetry = solveAgain(newton_, 0, "geometry retry",
                                           "with the geometry in Newton and its full terms");
      }
      // A contact Newton that failed with full steps (cycling statuses, overshooting iterates)
      // often converges at the same increment when each step must decrease ||R||: the
      // frictional hex27 tube's unloading failed down to the smallest step and converges in 9
      // iterations so (doc/algorithms.md "Line search retry").
      if (!ok && retry_ && (lastTry || options_.lineSearchRetry == "every-failure") &&
          iteratesFailedToConverge(report.failure)) {
        ++report.lineSearchRetries;
        ok = sr.lineSearchRetry =
            solveAgain(*retry_, 0, "line-search retry", "with the Backtrack line search");
      }
      // Generalized Newton's default `pairing` terms hold the master's normal in the tangent;
      // where the master dents and its normal turns, that tangent is not the residual's and
      // Newton may not settle even with a line search (the NAFEMS roller under its force),
      // and the consistent one converges: a step the line-search retry did not save is solved
      // again by it with the full terms, which the retry after it keeps (doc/algorithms.md
      // "Geometry retry"). After the line-search retry: a failure of cycling statuses (a
      // penalty's friction) costs the full steps nothing more.
      std::optional<FullGeometricTerms> fullTerms;
      if (!ok && retry_ && (lastTry || options_.lineSearchRetry == "every-failure") &&
          fullTermsRetryApplies() && iteratesFailedToConverge(report.failure)) {
        ++report.geometryRetries;
        fullTerms.emplace(*this);
        ok = sr.geometryRetry = solveAgain(*retry_, 0, "geometry retry",
                                           "with the Backtrack line search and the geometry's "
                                           "full terms");
      }
      // A forced cycling status can be one the step cannot reach: pulling an expanded tube out
      // of its tubesheet, every joint point's slip turns from the expansion's direction to the
      // pull's, the slip reversals detected on the way are forced to stick, and the forced
      // state climbs to ||R|| 1e10, with the line search too, down to the smallest cut. Without
      // a treatment the line search converges (doc/algorithms.md "Untreated retry"). Only
      // where a status was forced: elsewhere it would repeat the line-search retry.
      if (!ok && retry_ && stepForced_ &&
          (lastTry || options_.lineSearchRetry == "every-failure") &&
          iteratesFailedToConverge(report.failure)) {
        ++report.lineSearchRetries;
        untreated_ = true;
        ok = sr.lineSearchRetry = solveAgain(*retry_, 0, "untreated retry",
                                             "with the Backtrack line search and no cycling "
                                             "treatment");
        untreated_ = false;
      }
      // Full steps that failed through an update longer than the limit: a tangent nearly
      // singular (a perfectly plastic tube at its limit load before it meets the hole) threw the
      // iterate out, and ||R|| is flat along that mode, so the line search creeps; with the
      // updates limited Newton walks along it (doc/algorithms.md "Update limit"). Whatever the
      // failure (iterates that did not settle; a tangent that cannot be factorized, or an
      // element inverted, at a far-flung iterate); where no update was that long, the same
      // steps would fail again. After the line-search retry, so that what it saved is
      // unchanged.
      if (!ok && updateLimit > 0 && sr.longestUpdate > updateLimit)
        ok = sr.updateLimitRetry =
            solveAgain(newton_, updateLimit, "update-limit retry",
                       "with updates limited to " + scientificText(updateLimit));
    } catch (const Interrupted& i) {
      // The last converged step stays the result; the summary says why the run stopped.
      report.failure = "interrupted";
      report.message = std::string("interrupted by ") +
                       (i.signal == SIGINT ? "SIGINT" : "SIGTERM") +
                       " during the step to t = " + scientificText(sr.time) +
                       "; the results are those of " + "the last converged step";
      report.interruptSignal = i.signal;
      report.iterations += sr.iterations;
      return report;
    }
    account(sr, report);
    if (!ok) {
      if (lastTry) {
        if (options_.maxCuts > 0) {
          report.failure = "step-too-small";
          report.message = "the step to t = " + scientificText(sr.time) + " still failed " +
                           (cuts == options_.maxCuts
                                ? "after " + std::to_string(cuts) + " cuts (Load Steps/Max Cuts)"
                                : "at dt = " + scientificText(dt) +
                                      ", the smallest step (its nominal step / 2^Max Cuts)") +
                           "; last: " + report.message;
        } else if (iteratesFailedToConverge(report.failure)) {
          // A failed step is not cut by default (studies count failures); say how to cut it.
          report.message +=
              " (Load Steps/Max Cuts = 0: the step was not cut; a shorter step "
              "may pass, e.g. Max Cuts: 4)";
        }
        return report;
      }
      ++cuts;
      ++report.cuts;
      dt = h / 2;
      report.failure.clear();
      report.message.clear();
      continue;
    }
    extrapolation_.record(u, *x);
    sr.continuation.increment = extrapolation_.increment();
    sr.continuation.load = extrapolation_.load();
    u.assign(*x);
    slowDynamics_.commit(problem_, u, sr.time);
    sr.continuation.slowDynamicsPrevious = slowDynamics_.previousState();
    sr.continuation.slowDynamicsStep = slowDynamics_.previousStep();
    problem_.commitState(u, sr.time);
    ++report.steps;
    sr.nextStepSize = cuts == 0 ? std::min(2 * dt, nominal) : dt;
    // Into a nominal step of another length (Load Steps/Times): the same fraction of it, so
    // that steps without cuts end on each entry.
    if (const double next = options_.nominalStep(sr.time).length; next != nominal)
      sr.nextStepSize *= next / nominal;
    sr.loadReference = loadReference_;
    sr.run = report.totals();
    const auto t0 = std::chrono::steady_clock::now();
    if (onStep) onStep(sr, u);
    report.seconds.output += secondsSince(t0);
    t = sr.time;
    dt = sr.nextStepSize;
    cuts = 0;
    if (start.maxSteps > 0 && report.steps >= start.maxSteps &&
        t < options_.endTime * (1 - 1e-12)) {
      report.paused = true;
      return report;
    }
  }
  report.converged = true;
  return report;
}

}  // namespace contactlab
