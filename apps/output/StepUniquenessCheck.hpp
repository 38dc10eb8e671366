#pragma once
// Output/Critical Mu Check: after each converged step, the uniqueness check of `contactlab
// critical-mu` on that step's state, with a second instance of the scene's linear solver that
// computes determinants (their signs decide local uniqueness). Gives steps.csv the smallest
// critical mu over the frictional zones, and warns when the state is possibly non-unique (the
// verdict of `critical-mu`, uniquenessVerdict).
#include "algorithms/StaticSolver.hpp"
#include "apps/Console.hpp"
#include "apps/SceneModel.hpp"
#include "formulations/ContactProblem.hpp"
#include "linear/LinearSolver.hpp"

#include <memory>
#include <string>

namespace contactlab {

class StepUniquenessCheck {
 public:
  // Builds the solver (collective); the scene's solver must compute determinants
  // (requireDeterminantSolver).
  StepUniquenessCheck(const SceneModel& sm, ContactProblem& contact,
                      const Teuchos::RCP<const Comm>& comm, const Console& console);

  // Collective. The steps.csv cell of the converged state x of `step`: mu_crit, "inf" (no
  // critical mu) or "singular" (a Jacobian the solver could not factor).
  std::string check(const StepReport& step, const Vector& x);

  // Steps whose state was possibly non-unique so far.
  int possiblyNonUnique() const { return possiblyNonUnique_; }

 private:
  const SceneModel& sm_;
  ContactProblem& contact_;
  const Console console_;
  std::unique_ptr<LinearSolver> solver_;
  int possiblyNonUnique_ = 0;
};

}  // namespace contactlab
