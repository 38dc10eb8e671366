#pragma once
// Quasi-static load stepping with a plain Newton loop on R(u, t) = 0: the foundation's driver.
// Per step: prescribed values at the new time, then Newton until
//   ||R|| <= max(Absolute Tolerance, Relative Tolerance * ||R at the step's first iterate||).
// The contact algorithms (fixed point, generalized and partial Newton on NOX) come on top.
#include "core/problem/Problem.hpp"
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
  int iterations = 0;  // Newton iterations (linear solves) of this step
  double residual = 0;
  PhaseSeconds seconds;
};

struct RunReport {
  bool converged = false;
  std::string failure;  // empty, or a named reason: "diverged", "max-iterations",
                        // "nan-detected", "linear-solver-failed"
  std::string message;  // one sentence for the user
  int steps = 0;        // converged steps
  int iterations = 0;   // total Newton iterations
  int linearSolves = 0;
  PhaseSeconds seconds;
};

class StaticSolver {
 public:
  using StepCallback = std::function<void(const StepReport&, const Vector& u)>;
  using IterationCallback =
      std::function<void(int step, int steps, int iteration, double residual)>;

  StaticSolver(Problem& problem, LinearSolver& solver, StaticSolverOptions options);

  // Starts from u (the initial state, usually zero). After each converged step, u holds the
  // solution and onStep runs (results are written there). Never throws on a numerical failure:
  // the report names it, and u keeps the last converged step.
  RunReport run(Vector& u, const StepCallback& onStep, const IterationCallback& onIteration = {});

 private:
  Problem& problem_;
  LinearSolver& solver_;
  const StaticSolverOptions options_;
};

}  // namespace contactlab
