#pragma once
// The load steps of a system with the Newton method its options name (Newton/Driver: plain or
// nox), in one call: what the application, the benchmarks and the tests all do.
#include "algorithms/StaticSolver.hpp"
#include "linear/LinearSolver.hpp"

#include <memory>

namespace contactlab {

class NewtonMethod;

// The same as an object that can pause after RunStart::maxSteps steps and go on where it paused
// with its own state (slow dynamics' last velocity, the step extrapolation): a Simulation steps
// with it. Its calls after the first pass RunStart::resume.
class StaticRun {
 public:
  StaticRun(NonlinearSystem& system, ContactControls* controls, LinearSolver& solver,
            const StaticSolverOptions& options);
  ~StaticRun();
  RunReport run(Vector& u, const StaticSolver::StepCallback& onStep,
                const StaticSolver::IterationCallback& onIteration, const RunStart& start);

 private:
  std::unique_ptr<NewtonMethod> newton_, retry_;
  std::unique_ptr<StaticSolver> solver_;
};

// `controls` may be null (no contact). u: initial state in, last converged state out.
RunReport runStatic(NonlinearSystem& system, ContactControls* controls, LinearSolver& solver,
                    const StaticSolverOptions& options, Vector& u,
                    const StaticSolver::StepCallback& onStep = {},
                    const StaticSolver::IterationCallback& onIteration = {},
                    const RunStart& start = {});

}  // namespace contactlab
