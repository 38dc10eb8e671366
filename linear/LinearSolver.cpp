#include "linear/LinearSolver.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

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

double conditionLowerBound(const Matrix& A, const MultiVector& b, const MultiVector& x) {
  const auto local = A.getLocalMatrixHost();
  double localMax = 0.0;
  for (std::size_t k = 0; k < local.values.extent(0); ++k)
    localMax = std::max(localMax, std::fabs(local.values(k)));
  double maxEntry = 0.0;
  Teuchos::reduceAll(*A.getComm(), Teuchos::REDUCE_MAX, localMax, Teuchos::outArg(maxEntry));
  const std::size_t n = b.getNumVectors();
  std::vector<double> bNorms(n), xNorms(n);
  b.norm2(Teuchos::ArrayView<double>(bNorms));
  x.norm2(Teuchos::ArrayView<double>(xNorms));
  double bound = 0.0;
  for (std::size_t j = 0; j < n; ++j)
    if (bNorms[j] > 0.0) bound = std::max(bound, maxEntry * xNorms[j] / bNorms[j]);
  return bound;
}

void throwIfNumericallySingular(const Matrix& A, const MultiVector& b, const MultiVector& x) {
  const double bound = conditionLowerBound(A, b, x);
  if (!(bound > kSingularConditionBound)) return;  // NaN is not singularity: others name it
  char buffer[160];
  std::snprintf(buffer, sizeof buffer,
                "the matrix is numerically singular: the solution proves cond(A) >= %.1e "
                "(max |A_ij| ||x|| / ||b||)",
                bound);
  throw SingularMatrixError(buffer);
}

}  // namespace contactlab
