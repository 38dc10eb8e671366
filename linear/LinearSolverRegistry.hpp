#pragma once
// The linear solver axis: `Type: mumps` (the default in scenes), `klu2` or `belos`, plus a
// sibling sublist named after the type with that solver's parameters.
#include "base/Registry.hpp"
#include "linear/LinearSolver.hpp"

#include <memory>
#include <string>

namespace contactlab {

using LinearSolverRegistry = Registry<LinearSolver, Teuchos::RCP<const Comm>>;

LinearSolverRegistry& linearSolverRegistry();
// Registers mumps, klu2 and belos (idempotent). Builders validate their list again and throw
// LinearSolverError on an invalid one.
void registerLinearSolvers();

// Whether solver `type` can compute its matrix's determinant. The convention: such a solver
// declares a bool parameter `Determinant` (default false) in its valid parameters, so the
// registry, not a list of names, says which ones can.
bool computesDeterminant(const std::string& type);

// A solver that can read a symmetric matrix's one triangle declares a string parameter `Mode`
// whose default `automatic` leaves the choice to the application, which knows whether its
// tangent is symmetric (the convention, as `Determinant`'s). In the scene's Linear Solver section
// `section` ({Type, <type>: {...}}), an `automatic` Mode of such a type becomes
// `symmetric-indefinite` (LDL^T with 2x2 pivots) or `general` (LU); nothing changes for a type
// without the parameter or a Mode given. Written into the scene, so summary.json reports it.
void resolveAutomaticMode(Teuchos::ParameterList& section, bool symmetric);
// The section's Mode `general` (when its type has one): what a solver that dropped its symmetry
// for the run (LinearSolver::takeAnyMatrix) ran in.
void recordGeneralMode(Teuchos::ParameterList& section);

// The solvers of the registry that can compute a determinant, comma-separated.
std::string solversComputingDeterminant();

// Solver `type` built from its parameters `params` with `Determinant: true`, for the
// uniqueness checks, which read the signs of the determinants. Throws LinearSolverError when
// `type` cannot compute one (computesDeterminant).
std::unique_ptr<LinearSolver> buildDeterminantSolver(const std::string& type,
                                                     const Teuchos::ParameterList& params,
                                                     const Teuchos::RCP<const Comm>& comm);

}  // namespace contactlab
