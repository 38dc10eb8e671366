#pragma once
// The critical friction coefficient of the status pattern of a state (doc/theory.md): with
// every contact point's status held (no contact, stick or slip, as the state has them), the
// Jacobian is affine in the friction coefficients, J(s) = A + s B for a common factor s on
// every zone's mu (s = 1: the model). Its critical factor is the smallest s > 0 with
// det J(s) = 0.
//
// B is nonzero only in the rows of the friction laws of slipping points (k of them), so with
// J1 = J(1) factorized once and X = J1^-1 E_R (k solves, E_R the identity's columns at those
// rows), det J(s) = det J1 det(I_k + (s - 1) B_R X): a k x k dense generalized eigenvalue
// problem (CriticalFriction.hpp), exact, in place of a sparse eigensolver on the n x n pencil.
#include "core/problem/NonlinearSystem.hpp"
#include "formulations/ContactControls.hpp"
#include "linear/LinearSolver.hpp"

#include <optional>
#include <string>
#include <vector>

namespace contactlab {

struct PatternCriticalFriction {
  double scale = 0;                        // critical factor on every mu (+infinity: none)
  int frictionRows = 0;                    // k: rows of J that depend on mu
  int realRoots = 0;                       // real roots of det J(s)
  std::optional<Determinant> determinant;  // det J(1), when the solver computes it
};

// Collective. Holds `statuses` (per contact point 0 no contact, 1 stick, 2 slip; empty: those of
// an evaluation at x, t), assembles J at two friction factors, factorizes J(1) with `solver`,
// and restores the system (statuses released, factor 1, tangent reassembled at x). Throws
// LinearSolverError when J(1) is singular.
PatternCriticalFriction patternCriticalFriction(NonlinearSystem& system, ContactControls& controls,
                                                LinearSolver& solver, const Vector& x, double t,
                                                std::vector<int> statuses = {});

// The base of the generalized Jacobian around a converged state x: the points within
// `tolerance` of a status switch (|contact indicator| <= tolerance times its largest value;
// for closed points with friction, |friction indicator| <= tolerance) are ambiguous and take
// each adjacent status. Every combination is examined when there are at most `maxPatterns`;
// beyond, the converged pattern and each single change of one ambiguous point (the first
// maxPatterns of them), as `choice` says. Locally unique when every determinant has the same
// sign (known only with a solver that computes determinants).
// The critical mu also looks beyond the adjacent patterns at one more: every closed point
// slipping (in the direction of its traction). A sticking contact set is locally unique
// whatever mu, yet above that pattern's critical mu a slipping state of the same contact set may
// coexist with it, and separated states too (Hassani, Hild, Ionescu & Sakki 2003 set the
// critical friction on the slipping contact set). `scale` is the smaller of the two.
// Cost: the converged pattern is factorized once (k solves for its k rows that depend on mu);
// a pattern whose J(1) differs from it in q <= maxUpdateRows rows costs q solves with that
// factorization (Sherman-Morrison-Woodbury) and dense algebra of size k, in place of its own
// factorization and k solves (maxUpdateRows = 0: every pattern factorized).
struct UniquenessCheck {
  int ambiguousPoints = 0;
  int patterns = 0;  // examined
  std::string choice;
  bool signsKnown = false;
  bool sameSign = true;
  std::string breakingPattern;  // the first pattern whose sign differs (point: status, ...)
  int singularPatterns = 0;     // J(1) singular there (counted as breaking the sign)
  double localScale = 0;        // smallest critical factor over the adjacent patterns
  double slipScale = 0;         // of the contact set slipping (+infinity: no closed point)
  double scale = 0;             // min(localScale, slipScale)
  int frictionRows = 0;         // the largest k (rows that depend on mu) over the patterns
  int updatedPatterns = 0;      // examined by updates of the converged pattern's factorization
};
UniquenessCheck checkUniqueness(NonlinearSystem& system, ContactControls& controls,
                                LinearSolver& solver, const Vector& x, double t,
                                double tolerance = 1e-6, int maxPatterns = 64,
                                int maxUpdateRows = 256);

}  // namespace contactlab
