#include "linear/LinearSolver.hpp"

#include <cmath>

namespace contactlab {

double Determinant::log10Abs() const {
  return std::log10(std::fabs(mantissa)) + static_cast<double>(exponent) * std::log10(2.0);
}

}  // namespace contactlab
