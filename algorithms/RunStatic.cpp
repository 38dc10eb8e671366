#include "algorithms/RunStatic.hpp"

#include "algorithms/NoxNewton.hpp"
#include "algorithms/PlainNewton.hpp"

#include <memory>

namespace contactlab {

StaticRun::StaticRun(NonlinearSystem& system, ContactControls* controls, LinearSolver& solver,
                     const StaticSolverOptions& options) {
  if (options.driver == "nox")
    newton_ =
        std::make_unique<NoxNewton>(system, solver, controls, options.lineSearch, options.nox);
  else
    newton_ = std::make_unique<PlainNewton>(system, solver, controls);
  // The failed step's second try (Newton/Line Search Retry): NOX with Backtrack, the NOX
  // pass-through parameters too; none when the first try already searches along its steps.
  if (options.lineSearch == "Full Step")
    retry_ = std::make_unique<NoxNewton>(system, solver, controls, "Backtrack", options.nox);
  solver_ =
      std::make_unique<StaticSolver>(system, controls, *newton_, options, &solver, retry_.get());
}

StaticRun::~StaticRun() = default;

RunReport StaticRun::run(Vector& u, const StaticSolver::StepCallback& onStep,
                         const StaticSolver::IterationCallback& onIteration,
                         const RunStart& start) {
  return solver_->run(u, onStep, onIteration, start);
}

RunReport runStatic(NonlinearSystem& system, ContactControls* controls, LinearSolver& solver,
                    const StaticSolverOptions& options, Vector& u,
                    const StaticSolver::StepCallback& onStep,
                    const StaticSolver::IterationCallback& onIteration, const RunStart& start) {
  return StaticRun(system, controls, solver, options).run(u, onStep, onIteration, start);
}

}  // namespace contactlab
