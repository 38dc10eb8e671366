#pragma once
// One Newton solve run by NOX (line-search based solver) on Tpetra vectors through Thyra: the
// system as a Thyra model evaluator, its Jacobian solved by the project's LinearSolver (MUMPS by
// default) through a small Thyra linear-op-with-solve factory. The line search is NOX's (Full
// Step, Backtrack, Polynomial, More'-Thuente); convergence is NOX's NormF combined with a contact
// status test, and a NOX observer hands each iterate to the driver (cycling detection).
// Scenes pick it with Newton/Driver: nox; Newton/NOX passes parameters through to NOX.
#include "algorithms/NewtonMethod.hpp"
#include "linear/LinearSolver.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace contactlab {

class NoxNewton : public NewtonMethod {
 public:
  NoxNewton(NonlinearSystem& system, LinearSolver& solver, const ContactControls* controls,
            std::string lineSearch, Teuchos::ParameterList noxParameters = {});
  NewtonOutcome solve(Vector& x, const NewtonRequest& request, const Observer& observer) override;

 private:
  NonlinearSystem& system_;
  LinearSolver& solver_;
  const ContactControls* controls_;
  const std::string lineSearch_;
  const Teuchos::ParameterList noxParameters_;
};

}  // namespace contactlab
