#pragma once
// Iterative solver: Belos CG (symmetric positive definite A) or GMRES, with an optional Ifpack2
// or MueLu preconditioner rebuilt at each setMatrix. Convergence means
// ||b - A x|| <= Tolerance * ||b|| for every column of b (unpreconditioned residual: CG applies
// the preconditioner on the left but iterates on the true residual, GMRES on the right). A solve
// that does not converge throws. The initial guess is zero, as for the direct solvers.
#include "linear/LinearSolver.hpp"
#include "linear/Preconditioners.hpp"

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <memory>

namespace contactlab {

class BelosSolver : public LinearSolver {
 public:
  enum class Method { cg, gmres };
  enum class Verbosity { none, summary, iterations };

  struct Options {
    Method method = Method::cg;
    double tolerance = 1e-10;
    int maxIterations = 1000;
    int restart = 100;  // GMRES: Krylov vectors kept between restarts
    Verbosity verbosity = Verbosity::none;
    PreconditionerOptions preconditioner;  // .symmetric is set from the method
  };

  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  static Options optionsFrom(const Teuchos::ParameterList& params);

  BelosSolver(const Options& options, const Teuchos::RCP<const Comm>& comm);
  ~BelosSolver() override;

  std::string name() const override { return "belos"; }
  std::string symmetryAssumption() const override;
  void setMatrix(const Teuchos::RCP<const Matrix>& A, bool patternChanged) override;
  void solve(const MultiVector& b, MultiVector& x) override;
  void setNearNullSpace(const Teuchos::RCP<const MultiVector>& nullSpace) override;

 private:
  struct Impl;  // keeps Belos out of this header
  const Options options_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace contactlab
