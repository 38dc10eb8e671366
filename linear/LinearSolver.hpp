#pragma once
// A linear solver for the assembled tangent. It knows nothing of contact or of the FE model.
// Life cycle: setMatrix(A, patternChanged) whenever A's values (or pattern) changed, then any
// number of solve() calls. A direct solver reuses its symbolic analysis while the pattern is
// unchanged. Failures throw LinearSolverError with a sentence that names the cause.
// Every method is collective over the communicator the solver was built with (and A's, which
// must be the same): all ranks call them in the same order, and all ranks throw together.
#include "base/LinearAlgebra.hpp"

#include <Teuchos_RCP.hpp>

#include <optional>
#include <stdexcept>
#include <string>

namespace contactlab {

class LinearSolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The matrix is singular to working precision: a direct solver met a zero pivot, or a solve
// returned an x too large for any matrix resolvable in double precision
// (throwIfNumericallySingular). Typed so that a caller can say what a singular matrix means
// for its model; this layer does not know.
class SingularMatrixError : public LinearSolverError {
 public:
  using LinearSolverError::LinearSolverError;
};

// max_j ||D^-1 x_j|| / ||D b_j||, D = diag(max_k |A_ik|)^(-1/2): a lower bound on
// cond_2(D A D) / max|D A D| (entries of D A D are of order one), so independent of the rows'
// units (columns with b_j = 0 skipped). Costs a pass over A's values.
double conditionLowerBound(const Matrix& A, const MultiVector& b, const MultiVector& x);

// Throws SingularMatrixError when conditionLowerBound(A, b, x) proves cond(A) beyond
// kSingularConditionBound. A direct solver does not always see a singular matrix: the pivot of
// the null direction is then round-off instead of zero, and x is of order ||b|| / round-off.
void throwIfNumericallySingular(const Matrix& A, const MultiVector& b, const MultiVector& x);

// cond(A) beyond 1 / (100 eps): x then has fewer than 2 significant digits. The round-off
// pivots of singular contact tangents lie above it, the regular tangents' solves decades below
// (doc/algorithms.md, "Load steps").
inline constexpr double kSingularConditionBound = 4.5e13;

// det = sign * mantissa * 2^exponent, 0.5 <= |mantissa| < 1 (never formed: it over/underflows).
struct Determinant {
  double mantissa = 0.0;
  long exponent = 0;
  int sign() const { return mantissa > 0 ? 1 : (mantissa < 0 ? -1 : 0); }
  double log10Abs() const;  // log10 |det|
  // Brings |mantissa| into [0.5, 1) by moving powers of two into the exponent.
  static Determinant normalized(double mantissa, long exponent);
};

struct LinearSolverStats {
  int analyses = 0;
  int factorizations = 0;        // numeric factorizations (preconditioner setups for Belos)
  int solves = 0;                // solve() calls, whatever the number of right-hand sides
  int iterations = 0;            // last solve, iterative solvers only (max over right-hand sides)
  double relativeResidual = -1;  // last solve, max_j ||b_j - A x_j|| / ||b_j||; -1: not computed
  // setMatrix calls answered without a factorization (direct solvers that reuse their factors):
  // the matrix equals the last factorized one, or differs from it on few rows and columns and
  // is solved through a low-rank correction (`corrections` of them).
  int reusedFactorizations = 0;
  int corrections = 0;
  int lastCorrectionRank = 0;  // rows and columns of the last correction
  // Factorizations in single precision (of `factorizations`), and the refined solves' work:
  // applications of the approximate inverse (single factors, or a correction) beyond one per
  // right-hand side, and the matrices factorized again in double because a refinement failed.
  int singlePrecisionFactorizations = 0;
  int refinementSteps = 0;
  int doublePrecisionFallbacks = 0;
  double analysisSeconds = 0;  // cumulated
  double factorizationSeconds = 0;
  double solveSeconds = 0;
  double correctionSeconds = 0;  // setting corrections up (entries of the inverse, dense LU)
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual std::string name() const = 0;
  // Empty when the solver takes any square matrix. Otherwise the setting that makes it assume
  // a symmetric matrix and the one that does not, as a sentence fragment (e.g. "Mode
  // 'symmetric' reads only the lower triangle (Mode: general does not)"): a system whose
  // tangent is not symmetric must not be given to such a solver.
  virtual std::string symmetryAssumption() const { return {}; }
  // From the next setMatrix on, the matrices may not be symmetric (a caller whose system was
  // symmetric changes its tangent): a solver that assumes symmetry drops the assumption for
  // good, at the cost of its analysis and factors; symmetryAssumption() is empty afterwards.
  virtual void takeAnyMatrix() {}
  // Called after A's values changed. patternChanged = true: the pattern may differ from the
  // last matrix's, so a solver that does not compare patterns analyses again (MUMPS compares
  // them itself and keeps the analysis of an equal pattern).
  virtual void setMatrix(const Teuchos::RCP<const Matrix>& A, bool patternChanged) = 0;
  // Solves A x = b. b and x live on A's range / domain maps. x's input values are ignored.
  virtual void solve(const MultiVector& b, MultiVector& x) = 0;
  // Near-null space of A on A's row map (e.g. the rigid-body modes in elasticity), used from the
  // next setMatrix by solvers that can exploit it (algebraic multigrid); others ignore it.
  virtual void setNearNullSpace(const Teuchos::RCP<const MultiVector>& /*nullSpace*/) {}
  // Only solvers that can compute them return a value (after setMatrix, or after solve for the
  // condition estimate, when requested in the solver's parameters).
  virtual std::optional<Determinant> determinant() const { return std::nullopt; }
  virtual std::optional<double> conditionEstimate() const { return std::nullopt; }
  // Counts and times of this solver's work so far; every solver keeps them in stats_.
  const LinearSolverStats& stats() const { return stats_; }
  // Counts from zero again (a solver kept for another run: apps/LinearSolverPool.hpp); what
  // the solver holds (analysis, factors) is kept.
  void resetStats() { stats_ = LinearSolverStats{}; }

 protected:
  LinearSolverStats stats_;
};

}  // namespace contactlab
