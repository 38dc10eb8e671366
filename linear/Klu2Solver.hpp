#pragma once
// Direct solver KLU2 through Amesos2. Debian's Trilinos 13.2 (GCC 12) miscompiles KLU2's
// non-transposed solve, which Amesos2 uses on more than one rank or for a non-contiguous map:
// wrong answers, no error (doc/architecture.md "Trilinos and Debian"). So this class gathers the
// matrix on rank 0, onto a one-rank communicator and a contiguous map [0, N): there Amesos2 takes
// its single-process path, which reads the CRS arrays as the CCS arrays of A^T and calls the
// transposed solve, the one that works. It runs on any number of ranks (serially on rank 0), and
// every solve is checked against the original matrix: a relative residual above the tolerance
// throws, so a wrong answer is never returned silently. Prefer MUMPS for anything large.
#include "linear/LinearSolver.hpp"

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <memory>

namespace contactlab {

class Klu2Solver : public LinearSolver {
 public:
  struct Options {
    double residualTolerance = 1e-8;  // max ||b - A x|| / ||b|| accepted after each solve
  };

  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  static Options optionsFrom(const Teuchos::ParameterList& params);

  Klu2Solver(const Options& options, const Teuchos::RCP<const Comm>& comm);  // collective
  ~Klu2Solver() override;
  Klu2Solver(const Klu2Solver&) = delete;
  Klu2Solver& operator=(const Klu2Solver&) = delete;

  std::string name() const override { return "klu2"; }
  // As for MUMPS, a pattern that differs from the analysed one gets a new analysis anyway.
  void setMatrix(const Teuchos::RCP<const Matrix>& A, bool patternChanged) override;
  void solve(const MultiVector& b, MultiVector& x) override;

 private:
  struct Impl;  // keeps Amesos2 out of this header
  const Options options_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace contactlab
