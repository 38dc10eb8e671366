#pragma once
// Direct solver MUMPS 5.5 through its C API, on the communicator of the solver (every rank
// takes part: PAR = 1). The matrix is given distributed and assembled (ICNTL(18) = 3), each rank
// passing its own rows; right-hand side and solution are centralized on rank 0 for the solve.
// Construction and destruction are collective (MUMPS JOB = -1 / -2): every rank must create
// and destroy the solver, in the same order as its other collective objects.
#include "linear/LinearSolver.hpp"

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace contactlab {

class MumpsSolver : public LinearSolver {
 public:
  // MUMPS' SYM: 0 = general (LU), 1 = symmetric positive definite (LDL^T without pivoting),
  // 2 = general symmetric (LDL^T with 1x1/2x2 pivots). Symmetric modes read the lower triangle.
  enum class Mode { general = 0, symmetric = 1, symmetricIndefinite = 2 };
  // MUMPS' ICNTL(7). SCOTCH comes with Debian's libmumps-ptscotch build (preferred by the
  // build when installed), METIS with neither. automatic: SCOTCH when built in and the matrix
  // has 5 000 unknowns or more, else PORD.
  enum class Ordering { automatic = -1, amd = 0, amf = 2, scotch = 3, pord = 4, qamd = 6 };
  // Whether this build's MUMPS has SCOTCH (libmumps-ptscotch).
  static bool hasScotch();
  // The precision of the factors. Solves with single-precision factors (SMUMPS) are refined in
  // double against the matrix itself (IterativeRefinement) to the backward error a correction
  // promises; a matrix whose single factors cannot get there is factorized in double, and the
  // solver keeps double from then on. automatic: single when the first analysis predicts at
  // least kSingleFactorizationFlops, else double.
  enum class Precision { automatic, doublePrecision, singlePrecision };
  // Precision automatic's threshold on the first analysis' predicted flops (RINFOG(1)): above
  // it a factorization takes seconds and single precision saves a good part of it; below, the
  // refinement's extra solves would eat the saving, and the small models of the regression gold
  // keep their round-off (doc/performance.md "Single-precision factors").
  static constexpr double kSingleFactorizationFlops = 1e10;

  struct Options {
    Mode mode = Mode::general;
    Ordering ordering = Ordering::automatic;
    int memoryRelaxation = 20;       // ICNTL(14), percent over the analysis' estimate
    bool determinant = false;        // ICNTL(33) at each factorization
    bool conditionEstimate = false;  // ICNTL(11) = 1 at each solve (costs more than the solve)
    // Reuse the last factorization for a matrix that equals it or differs from it on at most
    // maxCorrectionRank rows and columns (CapacitanceCorrection), when MUMPS' flop counts
    // predict that cheaper than a factorization. Off when determinant or conditionEstimate is
    // asked (they describe a factorized matrix).
    bool reuseFactorization = true;
    int maxCorrectionRank = 3000;
    // Double when determinant or conditionEstimate is asked (they describe the factors).
    Precision precision = Precision::automatic;
  };

  // What MUMPS' error analysis (ICNTL(11) = 1) reported for the first right-hand side of the
  // last solve (Arioli, Demmel, Duff 1989): forwardError <= omega1*cond1 + omega2*cond2.
  struct ErrorAnalysis {
    double omega1 = 0;  // RINFOG(7): componentwise backward error, max_i |r_i| / (|A||x|+|b|)_i
    double omega2 = 0;  // RINFOG(8): same with ||A_i||_inf ||x||_inf for rows where the first
                        // denominator is tiny
    double forwardError = 0;  // RINFOG(9): bound on ||x - x_exact||_inf / ||x||_inf
    double cond1 = 0;         // RINFOG(10): condition number tied to omega1
    double cond2 = 0;         // RINFOG(11): condition number tied to omega2
  };

  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  // `params` is validated against validParameters() here again (defaults filled in).
  static Options optionsFrom(const Teuchos::ParameterList& params);

  MumpsSolver(const Options& options, const Teuchos::RCP<const Comm>& comm);
  ~MumpsSolver() override;  // collective
  MumpsSolver(const MumpsSolver&) = delete;
  MumpsSolver& operator=(const MumpsSolver&) = delete;

  std::string name() const override { return "mumps"; }
  std::string symmetryAssumption() const override;
  // A symmetric mode becomes general (LU): the instances start over with SYM = 0 (collective).
  void takeAnyMatrix() override;
  // The pattern is compared with the analysed one even when patternChanged = false: a changed
  // pattern always gets a new analysis (it costs one reduction and an O(nnz) comparison).
  void setMatrix(const Teuchos::RCP<const Matrix>& A, bool patternChanged) override;
  void solve(const MultiVector& b, MultiVector& x) override;
  std::optional<Determinant> determinant() const override;
  // max(cond1, cond2) of the last solve's error analysis (see ErrorAnalysis): a condition number
  // of the system for that right-hand side, which bounds the forward error together with the
  // backward errors; not the 2-norm condition number of A.
  std::optional<double> conditionEstimate() const override;
  std::optional<ErrorAnalysis> errorAnalysis() const;
  // INFOG(12) after the last factorization: number of negative pivots, which is the number of
  // negative eigenvalues in the symmetric modes (inertia). Empty in general mode.
  std::optional<long> negativePivots() const;
  // ICNTL(14) currently used (raised once after a workspace-too-small error).
  int memoryRelaxation() const;
  // The ordering MUMPS' last analysis used (INFOG(7); it falls back silently when the one asked
  // for is not built in), or nullopt before any analysis.
  std::optional<Ordering> orderingUsed() const;
  // Whether the factors solves use now are single precision.
  bool singlePrecisionFactors() const;

 private:
  struct Impl;  // keeps the MUMPS headers and mpi.h out of this header
  void factorizeMatrix(const Teuchos::RCP<const Matrix>& A);
  // Analyses the held pattern on the double or the single-precision instance.
  void analyse(bool singlePrecision);
  // Factorizes the held values in the precision chosen (MumpsSolverPrecision.cpp), analysing
  // first where the instance has not; falls back to double when single precision fails.
  void factorize();
  void factorizeInDouble();
  // Whether the next factorization is single precision (decides it at the first analysis under
  // Precision automatic).
  bool factorizesInSingle();
  // After a successful factorization (of the instance singleFactors names) that took
  // `seconds`: the factors are held, their flops and size kept for the reuse rule, counted, and
  // the centralized importers made for A's maps.
  void recordFactorization(double seconds);
  bool reusesFactorization() const;
  // After a factorization of A: A becomes the reference later matrices are compared with, when
  // a correction could ever pay (none is kept for a cheap factorization).
  void keepReference(const Matrix& A);
  // Answers setMatrix(A) from the reference factorization when it pays; false: factorize A.
  bool correctFrom(const Teuchos::RCP<const Matrix>& A);
  // Entries (column, row) of the factorized matrix's inverse, sorted by column (host's list;
  // collective).
  std::vector<double> inverseEntries(const std::vector<std::pair<GO, GO>>& entries);
  // One MUMPS solve of the centralized right-hand sides `root` in place (collective).
  void solveCentralized(MultiVector& root);
  // x = A^-1 b through the correction: A0^-1 (b - P D y) (CapacitanceCorrection).
  void solveCorrected(const MultiVector& b, MultiVector& x);
  // x = A^-1 b with the factors as they are (single precision: rounded, so approximate).
  void solveWithFactors(const MultiVector& b, MultiVector& x);
  // A solve that is not a direct solve in double (a correction, single-precision factors),
  // refined against A to the correction's backward error (IterativeRefinement); factorizes A
  // in double when that fails.
  void solveRefined(const MultiVector& b, MultiVector& x);
  Options options_;  // mode: general after takeAnyMatrix
  std::unique_ptr<Impl> impl_;
};

}  // namespace contactlab
