#pragma once
// Dense building blocks of the uniqueness diagnostic (doc/algorithms.md "Uniqueness: the critical
// friction coefficient"). For a fixed status pattern the Jacobian of the augmented-Lagrangian
// operator is affine in the friction coefficient, J(mu) = A + mu B; the pattern's critical mu is
// the smallest positive real mu with det(A + mu B) = 0, a generalized eigenvalue problem A v = mu
// (-B) v (LAPACK dggev). The sign of det J tells whether the Jacobians around a solution agree
// (locally unique when every one has the same sign).
//
// Matrices are n x n, column major. For small systems only (dense); the sparse version of the
// diagnostic (MUMPS determinants, Anasazi shift-invert) is not written yet.
#include "linear/LinearSolver.hpp"

#include <vector>

namespace contactlab {

struct CriticalFriction {
  double mu = 0;      // smallest positive real root; +infinity when there is none
  int realRoots = 0;  // finite real generalized eigenvalues (roots of det(A + mu B))
  int infinite = 0;   // eigenvalues at infinity (B singular in those directions)
  int zero = 0;       // roots with |mu| <= zeroTolerance, not counted as critical
};

// Roots with |mu| <= zeroTolerance are structural, not critical: with multipliers scaled by
// the threshold (the augmented Lagrangian's Lambda = lambda_t / (mu p)), a sticking point's
// Jacobian is singular at mu = 0 exactly, whatever the mechanics. With zeroTolerance > 0, roots
// with |mu| >= 1 / zeroTolerance count as at infinity (round-off of an infinite eigenvalue).
// Throws std::runtime_error when LAPACK fails, std::invalid_argument on sizes.
CriticalFriction criticalFriction(int n, std::vector<double> A, std::vector<double> B,
                                  double zeroTolerance = 0.0);

// The same for the pencil (I - M) + s M of a rank-k update, det(I + (s - 1) M) = 0: its roots
// are s = 1 - 1 / lambda for the eigenvalues lambda of M (LAPACK dgeev, a few times cheaper
// than the QZ of dggev); lambda = 0 is a root at infinity. Same tolerances as above.
CriticalFriction criticalFactorOfUpdate(int k, std::vector<double> M, double zeroTolerance = 0.0);

// det A as sign, mantissa and power of two (never formed: no overflow), by LU with partial
// pivoting (LAPACK dgetrf). A singular matrix gives mantissa 0.
Determinant denseDeterminant(int n, std::vector<double> A);

}  // namespace contactlab
