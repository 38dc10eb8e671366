#pragma once
// The critical friction coefficient of the status pattern of a state (DESIGN.md §6): with
// every contact point's status held (no contact, stick or slip, as the state has them), the
// Jacobian is affine in the friction coefficients, J(s) = A + s B for a common factor s on
// every zone's mu (s = 1: the model). Its critical factor is the smallest s > 0 with
// det J(s) = 0.
//
// B is nonzero only in the rows of the friction laws of slipping points (k of them), so with
// J1 = J(1) factorized once and X = J1^-1 E_R (k solves, E_R the identity's columns at those
// rows), det J(s) = det J1 det(I_k + (s - 1) B_R X): a k x k dense generalized eigenvalue
// problem (CriticalFriction.hpp), exact, in place of a sparse eigensolver on the n x n pencil.
#include "core/problem/ContactControls.hpp"
#include "core/problem/NonlinearSystem.hpp"
#include "linear/LinearSolver.hpp"

#include <optional>

namespace contactlab {

struct PatternCriticalFriction {
  double scale = 0;                        // critical factor on every mu (+infinity: none)
  int frictionRows = 0;                    // k: rows of J that depend on mu
  int realRoots = 0;                       // real roots of det J(s)
  std::optional<Determinant> determinant;  // det J(1), when the solver computes it
};

// Collective. Evaluates the system at x, t, holds its statuses, assembles J at two friction
// factors, factorizes J(1) with `solver`, and restores the system (statuses released, factor
// 1, tangent reassembled at x). Throws LinearSolverError when J(1) is singular.
PatternCriticalFriction patternCriticalFriction(NonlinearSystem& system, ContactControls& controls,
                                                LinearSolver& solver, const Vector& x, double t);

}  // namespace contactlab
