#pragma once
// What one attempt at a load step took: StaticSolver fills it, its loops add their counts
// (FixedPointLoop::recordUpdate), and for a converged step the outputs (steps.csv) read it.
#include "algorithms/CyclingDetector.hpp"

#include <array>

namespace contactlab {

struct PhaseSeconds {
  double assembly = 0, linearSolve = 0, output = 0;
};

using CyclingCounts = std::array<int, kCyclingKinds>;  // events per CyclingKind (0 unused)

struct StepReport {
  int step = 0;  // 1-based, converged steps
  double time = 0;
  int cuts = 0;             // bisections before this step converged
  double nextStepSize = 0;  // the load-time increment the next step will try (a checkpoint's)
  // The run's totals up to this step, failed attempts included (a checkpoint carries them).
  int runIterations = 0, runLinearSolves = 0, runCuts = 0;
  int iterations = 0;           // Newton iterations (linear solves), failed attempts included
  int statusIterations = 0;     // status fixed-point updates that changed a status
  int thresholdIterations = 0;  // threshold fixed-point updates that moved a threshold
  int geometryIterations = 0;   // geometry updates that moved and restarted Newton
  double residual = 0;
  CyclingCounts cycling{};
  PhaseSeconds seconds;
};

}  // namespace contactlab
