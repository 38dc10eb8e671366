#include "linear/LinearSolver.hpp"

#include <cmath>

namespace contactlab {

double Determinant::log10Abs() const {
  return std::log10(std::fabs(mantissa)) + static_cast<double>(exponent) * std::log10(2.0);
}

Determinant Determinant::normalized(double mantissa, long exponent) {
  Determinant d;
  if (mantissa == 0.0 || !std::isfinite(mantissa)) {
    d.mantissa = mantissa;
    return d;
  }
  int e = 0;
  d.mantissa = std::frexp(mantissa, &e);  // |m| in [0.5, 1), exact (powers of two only)
  d.exponent = exponent + e;
  return d;
}

}  // namespace contactlab
