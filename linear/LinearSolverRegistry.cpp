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

bool computesDeterminant(const std::string& type) {
  const auto valid = linearSolverRegistry().get(type).validParameters();
  return valid->isParameter("Determinant") && valid->isType<bool>("Determinant");
}

namespace {

// The type's parameters in `section` when that type declares a string Mode, else null.
Teuchos::ParameterList* modeParameters(Teuchos::ParameterList& section) {
  const std::string type = section.get<std::string>("Type");
  const auto valid = linearSolverRegistry().get(type).validParameters();
  if (!valid->isParameter("Mode") || !valid->isType<std::string>("Mode")) return nullptr;
  return &section.sublist(type);
}

}  // namespace

void resolveAutomaticMode(Teuchos::ParameterList& section, bool symmetric) {
  Teuchos::ParameterList* params = modeParameters(section);
  if (!params || params->get<std::string>("Mode", "automatic") != "automatic") return;
  params->set("Mode", symmetric ? "symmetric-indefinite" : "general");
}

void recordGeneralMode(Teuchos::ParameterList& section) {
  if (Teuchos::ParameterList* params = modeParameters(section)) params->set("Mode", "general");
}

std::string solversComputingDeterminant() {
  std::string names;
  for (const std::string& name : linearSolverRegistry().names())
    if (computesDeterminant(name)) names += (names.empty() ? "" : ", ") + name;
  return names;
}

std::unique_ptr<LinearSolver> buildDeterminantSolver(const std::string& type,
                                                     const Teuchos::ParameterList& params,
                                                     const Teuchos::RCP<const Comm>& comm) {
  if (!computesDeterminant(type))
    throw LinearSolverError("linear solver '" + type +
                            "' does not compute a determinant (solvers that do: " +
                            solversComputingDeterminant() + ")");
  Teuchos::ParameterList withDeterminant(params);
  withDeterminant.set("Determinant", true);
  return linearSolverRegistry().get(type).build(withDeterminant, comm);
}

}  // namespace contactlab
