#include "linear/SolverParameters.hpp"

#include <cstdio>
#include <exception>

namespace contactlab {

std::string formatNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

Teuchos::ParameterList validatedParameters(const Teuchos::ParameterList& params,
                                           const Teuchos::ParameterList& valid,
                                           const std::string& solverName) {
  Teuchos::ParameterList copy(params);
  try {
    copy.validateParametersAndSetDefaults(valid);
  } catch (const std::exception& e) {
    throw LinearSolverError("invalid parameters for linear solver '" + solverName +
                            "': " + e.what());
  }
  return copy;
}

}  // namespace contactlab
