#pragma once
// Solves A x = b in double precision with an approximate inverse M^-1 of A: the factors of A in
// single precision, or a low-rank correction of the factors of an older matrix. x starts as
// M^-1 b and is refined by restarted GMRES on the residual equation, right-preconditioned by
// M^-1 and computed in double (GMRES-based iterative refinement: Carson & Higham, SIAM J. Sci.
// Comput. 40(2), 2018). Plain refinement (x += M^-1 r) stalls when cond(A) times the error of
// M^-1 nears one, where GMRES still converges in a few applications of M^-1
// (doc/performance.md, "Single-precision factors"). Knows MUMPS no more than contact.
#include "base/LinearAlgebra.hpp"

#include <functional>

namespace contactlab {

struct RefinementOptions {
  // Accept x when its normwise backward error ||b - A x||_inf / (||A||_inf ||x||_inf +
  // ||b||_inf) is at most this (a direct solve in double gives 1e-16 to 1e-12).
  double backwardErrorTarget = 1e-13;
  int maxApplications = 30;  // of M^-1 per column of b, the first one included
  int restart = 20;          // Krylov vectors per GMRES cycle
};

struct RefinementResult {
  bool converged = false;
  int applications = 0;      // of M^-1, over every column of b
  double backwardError = 0;  // the largest over the columns, at the end
};

// ||A||_inf over every rank (collective).
double normInf(const Matrix& A);

// x = A^-1 b through `applyInverse` (out = M^-1 in, on vectors of A's range map, collective),
// refined to options.backwardErrorTarget; normA = ||A||_inf. Each column of b is solved on its
// own. When the target is not met within options.maxApplications, x is the last iterate and
// the result says so. Collective.
RefinementResult refineSolution(
    const Matrix& A, double normA, const MultiVector& b, MultiVector& x,
    const std::function<void(const MultiVector&, MultiVector&)>& applyInverse,
    const RefinementOptions& options);

}  // namespace contactlab
