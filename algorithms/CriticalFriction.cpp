#include "algorithms/CriticalFriction.hpp"

#include <Teuchos_LAPACK.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace contactlab {
namespace {

void checkSize(int n, const std::vector<double>& M, const char* name) {
  if (n < 1 || M.size() != static_cast<std::size_t>(n) * n)
    throw std::invalid_argument(std::string(name) + " must be n x n with n >= 1");
}

// A finite real root of the determinant: counted, then structural (|mu| <= zeroTolerance), the
// round-off of a root at infinity (|mu| >= 1 / zeroTolerance) or a candidate critical value.
void addRealRoot(CriticalFriction& out, double mu, double zeroTolerance) {
  ++out.realRoots;
  if (std::fabs(mu) <= zeroTolerance)
    ++out.zero;
  else if (zeroTolerance > 0 && std::fabs(mu) >= 1 / zeroTolerance)
    ++out.infinite;
  else if (mu > 0 && mu < out.mu)
    out.mu = mu;
}

}  // namespace

CriticalFriction criticalFriction(int n, std::vector<double> A, std::vector<double> B,
                                  double zeroTolerance) {
  checkSize(n, A, "A");
  checkSize(n, B, "B");
  for (double& b : B)
    b = -b;  // A v = mu (-B) v
  std::vector<double> alphaR(n), alphaI(n), beta(n), work(1);
  double unused = 0;
  int info = 0;
  Teuchos::LAPACK<int, double> lapack;
  // Workspace query, then the solve.
  lapack.GGEV('N', 'N', n, A.data(), n, B.data(), n, alphaR.data(), alphaI.data(), beta.data(),
              &unused, 1, &unused, 1, work.data(), -1, &info);
  work.resize(static_cast<std::size_t>(std::max(work[0], 8.0 * n)));
  lapack.GGEV('N', 'N', n, A.data(), n, B.data(), n, alphaR.data(), alphaI.data(), beta.data(),
              &unused, 1, &unused, 1, work.data(), static_cast<int>(work.size()), &info);
  if (info != 0) throw std::runtime_error("LAPACK dggev failed, info = " + std::to_string(info));
  CriticalFriction out;
  out.mu = std::numeric_limits<double>::infinity();
  double scale = 0;
  for (int k = 0; k < n; ++k)
    scale = std::max(scale, std::hypot(alphaR[k], alphaI[k]));
  for (int k = 0; k < n; ++k) {
    // beta ~ 0 relative to alpha: an eigenvalue at infinity (det does not vanish for finite mu
    // along it). A complex pair is not a real root.
    if (std::fabs(beta[k]) <= 1e-14 * std::max(std::hypot(alphaR[k], alphaI[k]), 1e-300)) {
      ++out.infinite;
      continue;
    }
    if (std::fabs(alphaI[k]) > 1e-12 * std::max(scale, std::fabs(alphaR[k]))) continue;
    addRealRoot(out, alphaR[k] / beta[k], zeroTolerance);
  }
  return out;
}

CriticalFriction criticalFactorOfUpdate(int k, std::vector<double> M, double zeroTolerance) {
  checkSize(k, M, "M");
  std::vector<double> lambdaR(k), lambdaI(k), work(1);
  double unused = 0;
  int info = 0;
  Teuchos::LAPACK<int, double> lapack;
  lapack.GEEV('N', 'N', k, M.data(), k, lambdaR.data(), lambdaI.data(), &unused, 1, &unused, 1,
              work.data(), -1, &info);
  work.resize(static_cast<std::size_t>(std::max(work[0], 4.0 * k)));
  lapack.GEEV('N', 'N', k, M.data(), k, lambdaR.data(), lambdaI.data(), &unused, 1, &unused, 1,
              work.data(), static_cast<int>(work.size()), &info);
  if (info != 0) throw std::runtime_error("LAPACK dgeev failed, info = " + std::to_string(info));
  CriticalFriction out;
  out.mu = std::numeric_limits<double>::infinity();
  double scale = 0;
  for (int i = 0; i < k; ++i)
    scale = std::max(scale, std::hypot(lambdaR[i], lambdaI[i]));
  for (int i = 0; i < k; ++i) {
    const double size = std::hypot(lambdaR[i], lambdaI[i]);
    if (size <= 1e-14 * std::max(scale, 1.0)) {  // lambda = 0: s at infinity
      ++out.infinite;
      continue;
    }
    if (std::fabs(lambdaI[i]) > 1e-12 * std::max(scale, std::fabs(lambdaR[i]))) continue;
    addRealRoot(out, 1.0 - 1.0 / lambdaR[i], zeroTolerance);
  }
  return out;
}

Determinant denseDeterminant(int n, std::vector<double> A) {
  checkSize(n, A, "A");
  std::vector<int> pivots(n);
  int info = 0;
  Teuchos::LAPACK<int, double> lapack;
  lapack.GETRF(n, n, A.data(), n, pivots.data(), &info);
  if (info < 0) throw std::runtime_error("LAPACK dgetrf failed, info = " + std::to_string(info));
  if (info > 0) return Determinant::normalized(0.0, 0);  // exactly singular U
  double mantissa = 1.0;
  long exponent = 0;
  for (int k = 0; k < n; ++k) {
    int e = 0;
    mantissa *= std::frexp(A[static_cast<std::size_t>(k) * n + k], &e);
    exponent += e;
    if (pivots[k] != k + 1) mantissa = -mantissa;
    const Determinant d = Determinant::normalized(mantissa, exponent);  // keep it in range
    mantissa = d.mantissa;
    exponent = d.exponent;
  }
  return Determinant::normalized(mantissa, exponent);
}

}  // namespace contactlab
