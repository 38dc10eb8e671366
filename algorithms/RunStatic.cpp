#include "algorithms/RunStatic.hpp"

#include "algorithms/NoxNewton.hpp"
#include "algorithms/PlainNewton.hpp"

#include <memory>

namespace contactlab {

RunReport runStatic(NonlinearSystem& system, ContactControls* controls, LinearSolver& solver,
                    const StaticSolverOptions& options, Vector& u,
                    const StaticSolver::StepCallback& onStep,
                    const StaticSolver::IterationCallback& onIteration, const RunStart& start) {
  std::unique_ptr<NewtonMethod> newton;
  if (options.driver == "nox")
    newton = std::make_unique<NoxNewton>(system, solver, controls, options.lineSearch, options.nox);
  else
    newton = std::make_unique<PlainNewton>(system, solver, controls);
  // The failed step's second try (Newton/Line Search Retry): NOX with Backtrack, the NOX
  // pass-through parameters too; none when the first try already searches along its steps.
  std::unique_ptr<NewtonMethod> retry;
  if (options.lineSearch == "Full Step")
    retry = std::make_unique<NoxNewton>(system, solver, controls, "Backtrack", options.nox);
  return StaticSolver(system, controls, *newton, options, &solver, retry.get())
      .run(u, onStep, onIteration, start);
}

}  // namespace contactlab
