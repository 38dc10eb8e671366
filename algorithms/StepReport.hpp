#pragma once
// What one attempt at a load step took: StaticSolver fills it, its loops add their counts
// (FixedPointLoop::recordUpdate), and for a converged step the outputs (steps.csv) read it.
#include "algorithms/CyclingDetector.hpp"
#include "base/LinearAlgebra.hpp"

#include <Teuchos_RCP.hpp>

#include <array>

namespace contactlab {

struct PhaseSeconds {
  double assembly = 0, linearSolve = 0, output = 0;
};

using CyclingCounts = std::array<int, kCyclingKinds>;  // events per CyclingKind (0 unused)

// A run's totals up to a step, failed attempts included. A checkpoint carries them, so that a
// restarted run's summary counts the whole run.
struct RunTotals {
  int iterations = 0, linearSolves = 0, cuts = 0;
  int lineSearchRetries = 0;    // failed steps solved again by the line-search Newton
  int geometryRetries = 0;      // failed steps solved again with the geometry in Newton
  int limitedUpdates = 0;       // Newton updates scaled down to Newton/Max Update
  int unevaluableHalvings = 0;  // updates halved: their iterate could not be evaluated
  int roundoffStops = 0;        // Newton solves stopped at their residual's round-off floor
  int statusIterations = 0, thresholdIterations = 0, geometryIterations = 0;
  CyclingCounts cycling{};
};

// What a run continued after a step needs to start its next step as the uninterrupted run
// would (a checkpoint's last_step, a paused run's state): the step's increment and its plain
// start's residual (Newton/Extrapolation; null when the run does not extrapolate), and slow
// dynamics' state before the step with the step's length (null without slow dynamics;
// SlowDynamics::restorePrevious).
struct StepContinuation {
  Teuchos::RCP<const Vector> increment, load;
  Teuchos::RCP<const Vector> slowDynamicsPrevious;
  double slowDynamicsStep = 0;
};

struct StepReport {
  int step = 0;  // 1-based, converged steps
  double time = 0;
  int cuts = 0;                   // bisections before this step converged
  bool lineSearchRetry = false;   // converged by the line-search retry (Newton/Line Search Retry)
  bool updateLimitRetry = false;  // converged with its updates limited (Newton/Max Update)
  bool geometryRetry = false;     // converged with the geometry in Newton (Newton/Geometry Retry)
  double longestUpdate = 0;       // the largest displacement a Newton update of the step made
  double nextStepSize = 0;        // the load-time increment the next step will try (a checkpoint's)
  // The reference residual of the last step that did not hold the load (a checkpoint's): a held
  // step's tolerance is relative to a fraction of it (StaticSolver::solveStep).
  double loadReference = 0;
  RunTotals run;                // the run's totals up to this step
  int iterations = 0;           // Newton iterations (linear solves), failed attempts included
  int statusIterations = 0;     // status fixed-point updates that changed a status
  int thresholdIterations = 0;  // threshold fixed-point updates that moved a threshold
  int geometryIterations = 0;   // geometry updates that moved and restarted Newton
  double residual = 0;
  CyclingCounts cycling{};
  PhaseSeconds seconds;
  StepContinuation continuation;  // for a checkpoint, or the next step of a paused run
};

}  // namespace contactlab
