#pragma once
// Newton with full steps, each linear solve by the project's LinearSolver; the linear solver
// redoes its symbolic analysis only when the tangent's pattern changed.
#include "algorithms/NewtonMethod.hpp"
#include "linear/LinearSolver.hpp"

namespace contactlab {

class PlainNewton : public NewtonMethod {
 public:
  PlainNewton(NonlinearSystem& system, LinearSolver& solver, const ContactControls* controls)
      : system_(system), solver_(solver), controls_(controls) {}
  NewtonOutcome solve(Vector& x, const NewtonRequest& request, const Observer& observer) override;

 private:
  NonlinearSystem& system_;
  LinearSolver& solver_;
  const ContactControls* controls_;
};

}  // namespace contactlab
