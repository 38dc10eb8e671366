#include "linear/LinearSolverRegistry.hpp"

#include "linear/BelosSolver.hpp"
#include "linear/Klu2Solver.hpp"
#include "linear/MumpsSolver.hpp"

namespace contactlab {

LinearSolverRegistry& linearSolverRegistry() {
  static LinearSolverRegistry registry("linear solver");
  return registry;
}

void registerLinearSolvers() {
  auto& registry = linearSolverRegistry();
  registry.add({"mumps",
                "MUMPS sparse direct solver (LU or LDL^T) on all ranks; can report the "
                "determinant, the inertia and a condition estimate",
                &MumpsSolver::validParameters,
                [](const Teuchos::ParameterList& p, Teuchos::RCP<const Comm> comm) {
                  return std::unique_ptr<LinearSolver>(
                      new MumpsSolver(MumpsSolver::optionsFrom(p), comm));
                }});
  registry.add({"klu2",
                "Amesos2 KLU2 sparse LU, serial on rank 0 (the matrix is gathered there); "
                "every solve is checked by its residual. For small problems and cross-checks",
                &Klu2Solver::validParameters,
                [](const Teuchos::ParameterList& p, Teuchos::RCP<const Comm> comm) {
                  return std::unique_ptr<LinearSolver>(
                      new Klu2Solver(Klu2Solver::optionsFrom(p), comm));
                }});
  registry.add({"belos",
                "Belos CG or GMRES with an Ifpack2 or MueLu preconditioner; throws when it "
                "does not converge",
                &BelosSolver::validParameters,
                [](const Teuchos::ParameterList& p, Teuchos::RCP<const Comm> comm) {
                  return std::unique_ptr<LinearSolver>(
                      new BelosSolver(BelosSolver::optionsFrom(p), comm));
                }});
}

}  // namespace contactlab
