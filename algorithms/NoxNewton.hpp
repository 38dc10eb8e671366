#pragma once
// Newton iterations of one load step run by NOX (line-search based solver) on Tpetra vectors
// through Thyra: the problem is a Thyra model evaluator over a NonlinearSystem, its Jacobian
// solved by the project's LinearSolver (MUMPS by default) through a small Thyra
// linear-op-with-solve factory. First piece of the algorithms issue: the line searches of NOX
// (Full Step, Backtrack, Polynomial, More'-Thuente) with the geometric fixed point around them.
// Scenes pick it with Newton/Driver: nox and Newton/Line Search.
#include "algorithms/StaticSolver.hpp"
#include "core/problem/NonlinearSystem.hpp"
#include "linear/LinearSolver.hpp"

#include <string>

namespace contactlab {

struct NoxNewtonOptions {
  StaticSolverOptions steps;             // load steps, tolerances, iteration limits
  std::string lineSearch = "Full Step";  // NOX's "Line Search"/"Method"
};

class NoxNewton {
 public:
  NoxNewton(NonlinearSystem& system, LinearSolver& solver, NoxNewtonOptions options);
  // As StaticSolver::run: u holds the last converged step; failures are named, never thrown.
  RunReport run(Vector& x, const StaticSolver::StepCallback& onStep = {});

 private:
  NonlinearSystem& system_;
  LinearSolver& solver_;
  const NoxNewtonOptions options_;
};

}  // namespace contactlab
