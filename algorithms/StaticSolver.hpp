#pragma once
// Quasi-static load stepping with the seed's nested algorithms (doc/algorithms.md "Three non-smooth
// things, one loop each").
//
// Per load step: prescribed values at the new time (spread through the body by the tangent
// predictor when they moved), the geometry paired at the predictor, then a Newton solve
// (PlainNewton or NoxNewton) inside fixed points on whatever the method leaves to them,
// innermost first: contact statuses, friction thresholds, geometry, each a FixedPointLoop that
// the preset composed (algorithms/AlgorithmPresets.hpp) and that solveStep runs generically. A
// nonlinearity "in Newton" follows the iterate instead (statuses and thresholds through the
// formulation's generalized Jacobian; the geometry re-paired at every iterate, its derivatives
// in the tangent as Algorithm/Geometric Terms says: see doc/algorithms.md). Presets:
//   fixed-point          geometry, thresholds, statuses all fixed points
//   generalized-newton   all three in Newton
//   partial-newton       geometry a fixed point, thresholds and statuses in Newton
// Every Newton iterate feeds the cycling detector; the treatment (none, automatic, forced)
// acts on the cycling points for the rest of the step. A failed step is cut in two, up to
// Max Cuts times and never below End Time / Steps / 2^Max Cuts; steps that converge without a
// cut let the step grow back. Steps never pass a nominal time k End Time / Steps or a landing
// time (a load function's kink): cuts and regrowth would otherwise step over the peak of a
// load table. A failed step is solved once more by a backtracking line-search Newton before
// it is cut (Newton/Line Search Retry).
#include "algorithms/CyclingDetector.hpp"
#include "algorithms/FixedPointLoop.hpp"
#include "algorithms/NewtonMethod.hpp"
#include "algorithms/SlowDynamics.hpp"
#include "algorithms/StepExtrapolation.hpp"
#include "algorithms/StepReport.hpp"
#include "core/problem/NonlinearSystem.hpp"
#include "formulations/ContactControls.hpp"
#include "linear/LinearSolver.hpp"

#include <Teuchos_ParameterList.hpp>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace contactlab {

class SolidAlonePredictor;

struct StaticSolverOptions {
  int steps = 1;
  double endTime = 1.0;
  // The instants the steps end on (Load Steps/Times: increasing, the last one endTime), in
  // place of `steps` equal ones; empty: k endTime / steps.
  std::vector<double> times;
  int maxCuts = 0;  // bisections of a failed step (0: a failed step ends the run)
  // Load times a step must end on, besides the nominal ones k End Time / Steps: the kinks of
  // the load functions, output times (in any order; those outside (0, End Time) are ignored).
  std::vector<double> landingTimes;
  int maxIterations = 20;
  double relativeTolerance = 1e-8;
  double absoluteTolerance = 1e-12;
  int maxGeometryIterations = 30;
  double geometryTolerance = 1e-6;
  std::string driver = "plain";          // "plain" (PlainNewton) or "nox" (NoxNewton)
  std::string lineSearch = "Full Step";  // NOX line search (driver "nox" only)
  Teuchos::ParameterList nox;            // passed through to NOX
  // When a failed step is solved again by the line-search retry Newton (StaticSolver's
  // constructor): "every-failure" (before each cut, and before the run fails), "last-resort"
  // (only when the step cannot be cut any more), "never".
  std::string lineSearchRetry = "every-failure";
  int retryMaxIterations = 40;  // Newton iterations per solve of the line-search retry
  // A step whose geometric fixed point diverged (FixedPointLoop::diverged) is solved again with
  // the geometry in Newton and its full terms (the contact controls' GeometricTerms::full).
  bool geometryRetry = true;
  // While a fixed point (statuses, thresholds, geometry) still moves, the Newton solve after
  // one of its updates stops at fixedPointForcing times the residual the update left
  // (NewtonRequest::forcing; 0: at the step's target).
  double fixedPointForcing = 1e-2;
  // The largest displacement a plain Newton update may make when a step whose full steps failed
  // is solved again, as a fraction of the model's size (NonlinearSystem::modelSize); 0: no
  // such retry.
  double maxUpdate = 0.05;
  // A plain Newton solve gives up when this many iterates in a row had ||R|| above
  // kStallFactor times its first one (NewtonRequest::stallIterations); 0: never.
  int stallIterations = 8;
  // Whether a step whose prescribed values move starts from the tangent predictor
  // (doc/algorithms.md): "tangent", "solid-alone", "none", or "automatic".
  std::string predictor = "automatic";
  // Where a step after the first converged one starts: "none" (the last converged state),
  // "linear" (extrapolated from the last two: StepExtrapolation) or "automatic" (linear without
  // contact and for the status fixed point). A scene's Newton/Extrapolation defaults to
  // "automatic"; options built in code keep "none" unless they ask.
  std::string extrapolation = "none";
  // Algorithm.
  std::string method = "partial-newton";
  bool geometryInNewton = false, thresholdsInNewton = true, statusesInNewton = true;
  int maxStatusIterations = 30;
  int maxThresholdIterations = 30;
  double thresholdTolerance = 1e-3;
  std::string cyclingTreatment = "none";  // none | automatic | forced
  double grazingTolerance = 1e-6;
  GeometricTerms geometricTerms = GeometricTerms::pairing;  // with the geometry in Newton
  SlowDynamicsOptions slowDynamics;  // the regularization this solver applies (SlowDynamics)

  // The number of steps the load is divided into when no step is cut.
  int requestedSteps() const { return times.empty() ? steps : static_cast<int>(times.size()); }
  // The nominal step that holds time t: [k endTime / steps, (k+1) endTime / steps], or the
  // interval between two entries of `times` (the first from 0). A step that starts at t is
  // never longer, and never cut below its length / 2^maxCuts.
  struct NominalStep {
    double end = 0, length = 0;
  };
  NominalStep nominalStep(double t) const;

  static Teuchos::RCP<const Teuchos::ParameterList> validLoadSteps();
  static Teuchos::RCP<const Teuchos::ParameterList> validNewton();
  static Teuchos::RCP<const Teuchos::ParameterList> validAlgorithm();
  static StaticSolverOptions from(const Teuchos::ParameterList& loadSteps,
                                  const Teuchos::ParameterList& newton,
                                  const Teuchos::ParameterList& algorithm);
};

struct RunReport {
  bool converged = false;
  std::string failure;      // empty, or a named reason: "diverged", "max-iterations",
                            // "nan-detected", "linear-solver-failed", "singular-tangent" (the
                            // linear solver found the tangent singular: a body not held in
                            // some direction), "nonlinear-solver-error",
                            // "geometry-not-converged", "statuses-not-converged",
                            // "thresholds-not-converged", "material-update-failed",
                            // "inverted-element" (the solid cannot be evaluated at an
                            // iterate: see AssemblyFailure), "contact-geometry-failed" (the
                            // contact surfaces of an iterate cannot be paired or integrated: a
                            // collapsed mortar facet), "contact-passed-through" (slave
                            // nodes left their master through it: ContactControls::
                            // passedThrough), "degraded-contact" (a forced
                            // cycling treatment's state violates the contact law and Newton
                            // from it without the treatment failed), "step-too-small",
                            // "interrupted" (SIGINT or SIGTERM), "stopped" (a
                            // stepped Simulation finished before End Time)
  std::string message;      // one sentence for the user
  int interruptSignal = 0;  // failure "interrupted": the signal (SIGINT, SIGTERM)
  // RunStart::maxSteps steps converged before End Time: neither converged nor failed.
  bool paused = false;
  int steps = 0;       // converged steps
  int iterations = 0;  // total Newton iterations
  int statusIterations = 0, thresholdIterations = 0, geometryIterations = 0;
  int linearSolves = 0;
  int cuts = 0;
  int lineSearchRetries = 0;    // failed steps the line-search Newton solved again (or not)
  int geometryRetries = 0;      // failed steps solved again with the geometry in Newton
  int limitedUpdates = 0;       // Newton updates scaled down to Newton/Max Update
  int unevaluableHalvings = 0;  // updates halved: their iterate could not be evaluated
  int roundoffStops = 0;        // Newton solves stopped at their residual's round-off floor
  CyclingCounts cycling{};
  PhaseSeconds seconds;

  // The counts as a step's run totals, and the counts a continued run starts from.
  RunTotals totals() const {
    return {iterations,          linearSolves,       cuts,
            lineSearchRetries,   geometryRetries,    limitedUpdates,
            unevaluableHalvings, roundoffStops,      statusIterations,
            thresholdIterations, geometryIterations, cycling};
  }
  void startFrom(const RunTotals& t) {
    iterations = t.iterations, linearSolves = t.linearSolves, cuts = t.cuts;
    lineSearchRetries = t.lineSearchRetries, geometryRetries = t.geometryRetries;
    limitedUpdates = t.limitedUpdates;
    unevaluableHalvings = t.unevaluableHalvings;
    roundoffStops = t.roundoffStops;
    statusIterations = t.statusIterations, thresholdIterations = t.thresholdIterations;
    geometryIterations = t.geometryIterations, cycling = t.cycling;
  }
};

// Where a run starts: at rest at t = 0 (the default), or from a converged state of an earlier
// run (a checkpoint: apps/RunCheckpoint) at `time`, after `step` converged steps, with the step
// size that run would have tried next (0: End Time / Steps). A state handed in is taken as it
// is: the contact statuses and normal fields are not seeded again.
struct RunStart {
  double time = 0;
  int step = 0;
  double stepSize = 0;
  bool fromState = false;
  RunTotals totals;  // the counts so far: a killed run continued counts the whole run
  // The last step's continuation (StepReport::continuation), when the checkpoint kept it: the
  // first step extrapolates, and slow dynamics predicts, as the uninterrupted run's did.
  StepContinuation continuation;
  // The last loaded step's reference residual (StepReport::loadReference; 0: none yet).
  double loadReference = 0;
  // > 0: the run pauses after this many converged steps (RunReport::paused); a run started
  // from its last step's report (StepReport: time, nextStepSize, continuation,
  // loadReference, run) goes on as the uninterrupted run would.
  int maxSteps = 0;
  // The same StaticSolver's earlier run paused here (maxSteps): its own state goes on (slow
  // dynamics' velocity, the step extrapolation) instead of starting from this one's.
  bool resume = false;
};

class StaticSolver {
 public:
  using StepCallback = std::function<void(const StepReport&, const Vector& u)>;
  // One Newton iterate, as a progress line shows it.
  struct IterateProgress {
    int step = 0;
    double time = 0;           // the step's end (a cut step ends earlier than planned)
    int iteration = 0;         // in this attempt at the step (0: its start)
    double residual = 0;       // ||R|| as Newton goes on with it (after a cycling treatment)
    int treatedPoints = 0;     // points whose law a cycling treatment changed at this iterate
    const char* attempt = "";  // "" or how a failed step is being solved again
    // At a Newton solve's first iterate: the fixed point whose update restarted Newton
    // ("statuses", "thresholds", "geometry"), or "".
    const char* restartedBy = "";
    // What the iterate is measured against: the step's target, and (with contact) the status
    // changes and the contact rows' norm as forces at this iterate (ContactControls): below the
    // target with either left, Newton goes on (contactSettled).
    double target = 0;
    int statusChanges = 0;
    double contactResidual = 0;
  };
  using IterationCallback = std::function<void(const IterateProgress&)>;

  // `controls` is the system's contact seam, or null for a system without contact. `solver`
  // solves the tangent predictor's system (null: no predictor, whatever the options say).
  // `retry`, when given, solves a failed step again from its start (a line-search Newton) as
  // options.lineSearchRetry says.
  StaticSolver(NonlinearSystem& problem, ContactControls* controls, NewtonMethod& newton,
               StaticSolverOptions options, LinearSolver* solver = nullptr,
               NewtonMethod* retry = nullptr);
  ~StaticSolver();

  // Starts from u (the initial state, usually zero). After each converged step, u holds the
  // solution and onStep runs (results are written there). Never throws on a numerical failure:
  // the report names it, and u keeps the last converged step.
  RunReport run(Vector& u, const StepCallback& onStep, const IterationCallback& onIteration = {},
                const RunStart& start = {});

 private:
  // One attempt at the step to time t from the converged state u; x holds the result. maxUpdate
  // > 0 scales every longer Newton update down to it (NewtonRequest::maxUpdate).
  bool solveStep(NewtonMethod& newton, const Vector& u, Vector& x, StepReport& sr,
                 RunReport& report, const IterationCallback& onIteration, double maxUpdate = 0);
  // The end of a step of size dt from t: t + dt, or the end of t's nominal step or the first
  // landing time after t when t + dt would pass it.
  double stepEnd(double t, double dt) const;
  // The tangent predictor from the converged state u to the step's time, when the prescribed
  // values moved: x (u with the new prescribed values on entry) becomes u + du with
  // K(u) du = -R(u, t) - K(u)_{.D} du_D.
  struct Prediction {
    bool done = false;    // false: the prescribed values did not move (or no predictor)
    double residual = 0;  // ||R(u, t) + K(u)_{.D} du_D||, the linearized start's residual
    std::string failure;  // a named reason when the system could not be evaluated or solved
    std::string message;
  };
  Prediction predict(const Vector& u, Vector& x, StepReport& sr, RunReport& report);
  // Newton/Extrapolation: x (u with the step's prescribed values on entry, its geometry
  // paired) becomes the extrapolated start (StepExtrapolation), paired there. `moved`: x is the
  // guess; else x is unchanged (no extrapolation, no converged step to extrapolate from, a load
  // held or turned back, a guess that cannot be evaluated). plainResidual >= 0: the plain
  // start's ||R||, and `residual` holds R at x as it is now; -1: `residual` is scratch.
  struct ExtrapolatedStart {
    bool moved = false;
    double plainResidual = -1;
  };
  ExtrapolatedStart extrapolatedStart(const Vector& u, Vector& x, double t, Vector& residual);
  // The solid-alone predictor's step at x (SolidAlonePredictor): whether x moved.
  bool stepSolidAlone(Vector& x, double t, StepReport& sr);
  // Whether a status fixed point freezes the contact statuses between Newton solves (the fixed
  // point preset), where scaling a cycling point's coefficients cannot change the frozen status.
  bool statusLoopOutsideNewton() const;
  // Whether a diverging geometric fixed point is handed to the geometry retry (Newton/Geometry
  // Retry, a contact model, the geometry not in Newton yet).
  bool geometryRetryApplies() const;
  // The number of points whose law the treatment changed (a status forced, coefficients
  // scaled): the Newton method evaluates the iterate again when it is not zero.
  int treatCycling(const std::vector<CyclingEvent>& events, StepReport& sr);
  // Whether the step may end at x: true unless a forced treatment is in effect and the model's
  // own contact law, the forced statuses released, leaves a residual above `target` there.
  bool forcedStateHolds(const Vector& x, double t, double target, Vector& residual);
  // The geometric terms the options give the contact controls: the preset's with the geometry
  // in Newton, none with a geometric fixed point.
  GeometricTerms ownGeometricTerms() const;
  // While it lives, the controls' geometric terms are full (the consistent tangent) and the
  // linear solver is told that the tangent may not be symmetric; then they are the options'
  // own again. Generalized Newton's full-terms retry (Newton/Geometry Retry).
  class FullGeometricTerms {
   public:
    explicit FullGeometricTerms(StaticSolver& solver);
    ~FullGeometricTerms();
    FullGeometricTerms(const FullGeometricTerms&) = delete;
    FullGeometricTerms& operator=(const FullGeometricTerms&) = delete;

   private:
    StaticSolver& solver_;
  };
  // While it lives, the steps are solved with the geometry in Newton and its full terms (the
  // geometry retry): the loops composed so, and FullGeometricTerms.
  class GeometryInNewton {
   public:
    explicit GeometryInNewton(StaticSolver& solver);
    ~GeometryInNewton();
    GeometryInNewton(const GeometryInNewton&) = delete;
    GeometryInNewton& operator=(const GeometryInNewton&) = delete;

   private:
    StaticSolver& solver_;
    FullGeometricTerms terms_;
  };
  // Whether a failed step is solved again with the geometry's full terms: the geometry in
  // Newton from the start with fewer terms.
  bool fullTermsRetryApplies() const;

  NonlinearSystem& problem_;
  ContactControls* controls_;
  NewtonMethod& newton_;
  NewtonMethod* retry_;
  const StaticSolverOptions options_;
  LinearSolver* solver_;
  std::unique_ptr<SolidAlonePredictor> solidAlone_;  // built at its first use
  CyclingDetector detector_;
  // The step's loops, innermost first (composeLoops): statuses, thresholds, geometry.
  std::vector<std::unique_ptr<FixedPointLoop>> loops_;
  // The same with the geometry in Newton, for the geometry retry (composed at its first use),
  // and whether the step being solved has the geometry in Newton.
  std::vector<std::unique_ptr<FixedPointLoop>> geometryInNewtonLoops_;
  StepExtrapolation extrapolation_;  // the last converged step, for Newton/Extrapolation
  // The reference residual of the last step that was not a held load (solveStep).
  double loadReference_ = 0;
  SlowDynamics slowDynamics_;  // the regularizing inertia and its history of converged states
  bool geometryInNewton_;
  // The step's forced points (cycling treatment 'forced'), and whether treatments may still act
  // in it: after a forced state failed the check, the step goes on with the model's own law.
  std::vector<std::size_t> forcedPoints_;
  bool treating_ = true;
  // Whether a status was forced in any attempt at the current step, and whether the attempt
  // being solved treats no cycling (the untreated retry).
  bool stepForced_ = false, untreated_ = false;
  double forcedResidual_ = 0;
  MPI_Comm mpiComm_ = MPI_COMM_SELF;  // the system's ranks, which agree on an interruption
  const char* attempt_ = "";          // IterateProgress::attempt of the step being solved
};

}  // namespace contactlab
