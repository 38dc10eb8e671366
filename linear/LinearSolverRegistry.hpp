#pragma once
// The linear solver axis: `Type: mumps` (the default in scenes), `klu2` or `belos`, plus a
// sibling sublist named after the type with that solver's parameters.
#include "core/io/Registry.hpp"
#include "linear/LinearSolver.hpp"

namespace contactlab {

using LinearSolverRegistry = Registry<LinearSolver, Teuchos::RCP<const Comm>>;

LinearSolverRegistry& linearSolverRegistry();
// Registers mumps, klu2 and belos (idempotent). Builders validate their list again and throw
// LinearSolverError on an invalid one.
void registerLinearSolvers();

}  // namespace contactlab
