#pragma once
// Helpers shared by the solvers: number formatting for messages, and parameter handling: validation
// of a user list against the valid one (errors become LinearSolverError) and typed reads of
// enumerated strings through the validators declared in the valid list, so each name <-> value
// table exists once.
#include "linear/LinearSolver.hpp"

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>

#include <string>

namespace contactlab {

// A number for messages, e.g. "3.2e-09" (std::to_string prints 1e-12 as 0.000000).
std::string formatNumber(double value);

// A copy of `params` validated against `valid`, with defaults filled in.
Teuchos::ParameterList validatedParameters(const Teuchos::ParameterList& params,
                                           const Teuchos::ParameterList& valid,
                                           const std::string& solverName);

// The enumerator of the string parameter `name`, declared in `valid` with
// Teuchos::setStringToIntegralParameter<Enum>.
template <class Enum>
Enum enumParameter(const Teuchos::ParameterList& params, const Teuchos::ParameterList& valid,
                   const std::string& name) {
  auto validator =
      Teuchos::rcp_dynamic_cast<const Teuchos::StringToIntegralParameterEntryValidator<Enum>>(
          valid.getEntry(name).validator(), true);
  return validator->getIntegralValue(params.get<std::string>(name), name);
}

}  // namespace contactlab
