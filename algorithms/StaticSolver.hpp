#pragma once
// Quasi-static load stepping with a Newton loop on R(x, t) = 0.
// Per step: prescribed values at the new time, geometry frozen at the start state, then Newton
// until ||R|| <= max(Absolute Tolerance, Relative Tolerance * ||R at the step's first iterate||).
// When Newton has converged the geometry is updated at the solution (a fixed point on the
// geometry, as in the seed's partial Newton); if it moved, Newton goes on from there. Statuses
// and friction threshold are Newton variables here (generalized Jacobian of the formulation).
// The configurable algorithms (fixed point, generalized and partial Newton on NOX) come next.
#include "core/problem/NonlinearSystem.hpp"
#include "linear/LinearSolver.hpp"

#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <string>

namespace contactlab {

struct StaticSolverOptions {
  int steps = 1;
  double endTime = 1.0;
  int maxIterations = 20;
  double relativeTolerance = 1e-8;
  double absoluteTolerance = 1e-12;
  int maxGeometryIterations = 10;
  double geometryTolerance = 1e-6;
  std::string driver = "plain";          // "plain" (StaticSolver) or "nox" (NoxNewton)
  std::string lineSearch = "Full Step";  // NOX line search (driver "nox" only)

  static Teuchos::RCP<const Teuchos::ParameterList> validLoadSteps();
  static Teuchos::RCP<const Teuchos::ParameterList> validNewton();
  static StaticSolverOptions from(const Teuchos::ParameterList& loadSteps,
                                  const Teuchos::ParameterList& newton);
};

struct PhaseSeconds {
  double assembly = 0, linearSolve = 0, output = 0;
};

struct StepReport {
  int step = 0;  // 1-based
  double time = 0;
  int iterations = 0;          // Newton iterations (linear solves) of this step
  int geometryIterations = 0;  // geometry updates that moved and restarted Newton
  double residual = 0;
  PhaseSeconds seconds;
};

struct RunReport {
  bool converged = false;
  std::string failure;  // empty, or a named reason: "diverged", "max-iterations",
                        // "nan-detected", "linear-solver-failed",
                        // "geometry-not-converged"
  std::string message;  // one sentence for the user
  int steps = 0;        // converged steps
  int iterations = 0;   // total Newton iterations
  int geometryIterations = 0;
  int linearSolves = 0;
  PhaseSeconds seconds;
};

class StaticSolver {
 public:
  using StepCallback = std::function<void(const StepReport&, const Vector& u)>;
  using IterationCallback =
      std::function<void(int step, int steps, int iteration, double residual)>;

  StaticSolver(NonlinearSystem& problem, LinearSolver& solver, StaticSolverOptions options);

  // Starts from u (the initial state, usually zero). After each converged step, u holds the
  // solution and onStep runs (results are written there). Never throws on a numerical failure:
  // the report names it, and u keeps the last converged step.
  RunReport run(Vector& u, const StepCallback& onStep, const IterationCallback& onIteration = {});

 private:
  NonlinearSystem& problem_;
  LinearSolver& solver_;
  const StaticSolverOptions options_;
};

}  // namespace contactlab
