#pragma once
// A linear solver for the assembled tangent. It knows nothing of contact or of the FE model.
// Life cycle: setMatrix(A, patternChanged) whenever A's values (or pattern) changed, then any
// number of solve() calls. A direct solver reuses its symbolic analysis while the pattern is
// unchanged. Failures throw LinearSolverError with a sentence that names the cause.
#include <optional>
#include <stdexcept>
#include <string>

#include <Teuchos_RCP.hpp>

#include "core/problem/LinearAlgebra.hpp"

namespace contactlab {

class LinearSolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// det = sign * mantissa * 2^exponent, 0.5 <= |mantissa| < 1 (never formed: it over/underflows).
struct Determinant {
  double mantissa = 0.0;
  long exponent = 0;
  int sign() const { return mantissa > 0 ? 1 : (mantissa < 0 ? -1 : 0); }
  double log10Abs() const;  // log10 |det|
};

struct LinearSolverStats {
  int analyses = 0;
  int factorizations = 0;
  int solves = 0;
  int iterations = 0;            // last solve, iterative solvers only
  double analysisSeconds = 0;    // cumulated
  double factorizationSeconds = 0;
  double solveSeconds = 0;
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual std::string name() const = 0;
  // Called after A's values changed. patternChanged = true forces a new symbolic analysis.
  virtual void setMatrix(const Teuchos::RCP<const Matrix>& A, bool patternChanged) = 0;
  // Solves A x = b. b and x live on A's range / domain maps.
  virtual void solve(const MultiVector& b, MultiVector& x) = 0;
  // Only solvers that can compute them return a value (after setMatrix when requested in the
  // solver's parameters).
  virtual std::optional<Determinant> determinant() const { return std::nullopt; }
  virtual std::optional<double> conditionEstimate() const { return std::nullopt; }
  virtual const LinearSolverStats& stats() const = 0;
};

}  // namespace contactlab
