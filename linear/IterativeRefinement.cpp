#include "linear/IterativeRefinement.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace contactlab {

namespace {

// Normwise backward error of x for A x = b: ||b - A x||_inf / (||A||_inf ||x||_inf + ||b||_inf).
double backwardError(const Matrix& A, double normA, const Vector& b, const Vector& x,
                     Vector& residual) {
  A.apply(x, residual);
  residual.update(1.0, b, -1.0);
  const double scale = normA * x.normInf() + b.normInf();
  return scale > 0 ? residual.normInf() / scale : 0.0;
}

// Solves the k x k upper triangle of the Hessenberg matrix H (leading dimension ld, column-
// major: H[i + j * ld]) for y: H y = g.
std::vector<double> backSubstitute(const std::vector<double>& H, int ld,
                                   const std::vector<double>& g, int k) {
  std::vector<double> y(k);
  for (int i = k - 1; i >= 0; --i) {
    double s = g[i];
    for (int j = i + 1; j < k; ++j)
      s -= H[i + j * ld] * y[j];
    y[i] = s / H[i + i * ld];
  }
  return y;
}

// One column: x holds M^-1 b; refines it in place. Returns its backward error.
double refineColumn(const Matrix& A, double normA, const Vector& b, Vector& x,
                    const std::function<void(const MultiVector&, MultiVector&)>& applyInverse,
                    const RefinementOptions& options, int& applications) {
  const auto map = b.getMap();
  const int m = std::max(1, options.restart);
  Vector residual(map);
  // The Krylov vectors are allocated at the first cycle: most solves need none.
  std::unique_ptr<MultiVector> V, Z;
  const int ld = m + 1;
  std::vector<double> H(static_cast<size_t>(ld) * m), cs(m), sn(m), g(m + 1);
  for (;;) {
    const double error = backwardError(A, normA, b, x, residual);
    if (!(error > options.backwardErrorTarget) || applications >= options.maxApplications)
      return error;
    if (!V) {
      V = std::make_unique<MultiVector>(map, m + 1);
      Z = std::make_unique<MultiVector>(map, m);
    }
    // GMRES on A d = r, right-preconditioned by M^-1: d = M^-1 V y, starting from d = 0.
    const double beta = residual.norm2();
    if (!(beta > 0) || !std::isfinite(beta)) return error;
    V->getVectorNonConst(0)->update(1.0 / beta, residual, 0.0);
    std::fill(g.begin(), g.end(), 0.0);
    g[0] = beta;
    // ||r||_inf <= ||r||_2: a cycle may stop once the 2-norm estimate is below the target's
    // residual, halved for the estimate's own round-off; the explicit residual above decides.
    const double stopResidual =
        0.5 * options.backwardErrorTarget * (normA * x.normInf() + b.normInf());
    int k = 0;
    for (int j = 0; j < m && applications < options.maxApplications; ++j) {
      auto z = Z->getVectorNonConst(j);
      auto w = V->getVectorNonConst(j + 1);
      applyInverse(*V->getVector(j), *z);
      ++applications;
      A.apply(*z, *w);
      for (int i = 0; i <= j; ++i) {  // modified Gram-Schmidt
        const auto vi = V->getVector(i);
        const double h = vi->dot(*w);
        H[i + j * ld] = h;
        w->update(-h, *vi, 1.0);
      }
      const double norm = w->norm2();
      H[j + 1 + j * ld] = norm;
      if (norm > 0) w->scale(1.0 / norm);
      for (int i = 0; i < j; ++i) {  // the earlier rotations, then this column's own
        const double a = H[i + j * ld], c = H[i + 1 + j * ld];
        H[i + j * ld] = cs[i] * a + sn[i] * c;
        H[i + 1 + j * ld] = -sn[i] * a + cs[i] * c;
      }
      const double a = H[j + j * ld], c = H[j + 1 + j * ld];
      const double radius = std::hypot(a, c);
      if (!(radius > 0)) break;  // a zero column: nothing more to gain in this cycle
      cs[j] = a / radius;
      sn[j] = c / radius;
      H[j + j * ld] = radius;
      H[j + 1 + j * ld] = 0.0;
      g[j + 1] = -sn[j] * g[j];
      g[j] = cs[j] * g[j];
      k = j + 1;
      if (std::abs(g[j + 1]) <= stopResidual || norm == 0) break;
    }
    if (k == 0) return error;
    const std::vector<double> y = backSubstitute(H, ld, g, k);
    for (int i = 0; i < k; ++i)
      x.update(y[i], *Z->getVector(i), 1.0);
  }
}

}  // namespace

double normInf(const Matrix& A) {
  const auto local = A.getLocalMatrixHost();
  double norm = 0;
  for (LO r = 0; r < static_cast<LO>(local.numRows()); ++r) {
    double sum = 0;
    for (auto k = local.graph.row_map(r); k < local.graph.row_map(r + 1); ++k)
      sum += std::abs(local.values(k));
    norm = std::max(norm, sum);
  }
  double global = 0;
  Teuchos::reduceAll(*A.getComm(), Teuchos::REDUCE_MAX, norm, Teuchos::outArg(global));
  return global;
}

RefinementResult refineSolution(
    const Matrix& A, double normA, const MultiVector& b, MultiVector& x,
    const std::function<void(const MultiVector&, MultiVector&)>& applyInverse,
    const RefinementOptions& options) {
  RefinementResult result;
  const size_t columns = b.getNumVectors();
  applyInverse(b, x);  // every column at once: one multi-column solve
  int applications = static_cast<int>(columns);
  result.converged = true;
  for (size_t j = 0; j < columns; ++j) {
    // A right-hand side that is not finite is left as M^-1 gives it: there is nothing to refine,
    // and the caller's own checks name a NaN (Newton's nan-detected).
    if (!std::isfinite(b.getVector(j)->normInf())) continue;
    int used = 1;
    const double error = refineColumn(A, normA, *b.getVector(j), *x.getVectorNonConst(j),
                                      applyInverse, options, used);
    applications += used - 1;
    result.backwardError = std::max(result.backwardError, error);
    if (!(error <= options.backwardErrorTarget)) result.converged = false;
  }
  result.applications = applications;
  return result;
}

}  // namespace contactlab
