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
  // Rows scaled by their largest entry, D = diag(r_i^-1/2): a model mixes units (a stiff block
  // beside a soft one, displacement rows beside multiplier rows weighted by areas), and the
  // unscaled bound took a well-posed but badly scaled tangent (a 1e6-times-stiffer punch on a
  // patch test: 6.4e14) for a singular one. The scaled matrix D A D has entries of order one.
  const auto local = A.getLocalMatrixHost();
  const std::size_t rows = local.numRows();
  std::vector<double> scale(rows, 0.0);  // r_i^(1/2)
  for (std::size_t i = 0; i < rows; ++i) {
    double r = 0.0;
    for (auto k = local.graph.row_map(i); k < local.graph.row_map(i + 1); ++k)
      r = std::max(r, std::fabs(local.values(k)));
    scale[i] = std::sqrt(r);
  }
  const std::size_t n = b.getNumVectors();
  const auto bv = b.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<double> local2(2 * n, 0.0), global2(2 * n, 0.0);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < rows && i < bv.extent(0); ++i) {
      if (scale[i] == 0.0) continue;
      const double bs = bv(i, j) / scale[i], xs = xv(i, j) * scale[i];
      local2[2 * j] += bs * bs;
      local2[2 * j + 1] += xs * xs;
    }
  Teuchos::reduceAll(*A.getComm(), Teuchos::REDUCE_SUM, static_cast<int>(2 * n), local2.data(),
                     global2.data());
  double bound = 0.0;
  for (std::size_t j = 0; j < n; ++j)
    if (global2[2 * j] > 0.0)
      bound = std::max(bound, std::sqrt(global2[2 * j + 1] / global2[2 * j]));
  return bound;
}

void throwIfNumericallySingular(const Matrix& A, const MultiVector& b, const MultiVector& x) {
  const double bound = conditionLowerBound(A, b, x);
  if (!(bound > kSingularConditionBound)) return;  // NaN is not singularity: others name it
  char buffer[160];
  std::snprintf(buffer, sizeof buffer,
                "the matrix is numerically singular: the solution proves cond(D A D) >= %.1e "
                "(||D^-1 x|| / ||D b||, D scaling the rows by their largest entry)",
                bound);
  throw SingularMatrixError(buffer);
}

}  // namespace contactlab
