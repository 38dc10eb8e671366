#pragma once
// The load steps of a system with the Newton method its options name (Newton/Driver: plain or
// nox), in one call: what the application, the benchmarks and the tests all do.
#include "algorithms/StaticSolver.hpp"
#include "linear/LinearSolver.hpp"

namespace contactlab {

// `controls` may be null (no contact). u: initial state in, last converged state out.
RunReport runStatic(NonlinearSystem& system, ContactControls* controls, LinearSolver& solver,
                    const StaticSolverOptions& options, Vector& u,
                    const StaticSolver::StepCallback& onStep = {},
                    const StaticSolver::IterationCallback& onIteration = {},
                    const RunStart& start = {});

}  // namespace contactlab
