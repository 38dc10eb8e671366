// Sanity timings of MUMPS and Belos on a 3D Laplacian, not run by default (a few seconds to a
// minute). Run with
//   mpirun -np 2 unit_linear --gtest_also_run_disabled_tests --gtest_filter='*Timing*'
// Size from CONTACTLAB_TIMING_N (grid points per direction, default 46: 97 336 unknowns).
#include "LinearTestProblems.hpp"

#include "linear/BelosSolver.hpp"
#include "linear/MumpsSolver.hpp"

#include <Tpetra_Core.hpp>

#include <cstdio>
#include <cstdlib>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

// One analysis, factorization and solve of A x = b; the solver's stats time each phase.
const LinearSolverStats& solveOnce(LinearSolver& solver, const Teuchos::RCP<const Matrix>& A,
                                   const MultiVector& b, MultiVector& x) {
  solver.setMatrix(A, true);
  solver.solve(b, x);
  return solver.stats();
}

TEST(MumpsTiming, DISABLED_Laplacian3D) {
  const auto comm = Tpetra::getDefaultComm();
  const char* env = std::getenv("CONTACTLAB_TIMING_N");
  const int n = env ? std::atoi(env) : 46;
  const auto A = test::laplacian3D(n, test::Layout::contiguous, comm);
  const auto b = test::rightHandSide(*A, 1);
  for (auto mode : {MumpsSolver::Mode::symmetric, MumpsSolver::Mode::general}) {
    MumpsSolver::Options o;
    o.mode = mode;
    MumpsSolver solver(o, comm);
    MultiVector x(A->getDomainMap(), 1);
    const auto& s = solveOnce(solver, A, *b, x);
    if (comm->getRank() == 0)
      std::printf(
          "MUMPS %s, %lld unknowns, %d ranks: analysis %.2f s, factorization %.2f s, "
          "solve %.3f s\n",
          mode == MumpsSolver::Mode::general ? "general  " : "symmetric",
          static_cast<long long>(A->getGlobalNumRows()), comm->getSize(), s.analysisSeconds,
          s.factorizationSeconds, s.solveSeconds);
    EXPECT_LT(test::relativeResidual(*A, *b, x), 1e-10);
  }
}

TEST(BelosTiming, DISABLED_Laplacian3D) {
  using Kind = PreconditionerOptions::Kind;
  const auto comm = Tpetra::getDefaultComm();
  const char* env = std::getenv("CONTACTLAB_TIMING_N");
  const int n = env ? std::atoi(env) : 40;
  const auto A = test::laplacian3D(n, test::Layout::contiguous, comm);
  const auto b = test::rightHandSide(*A, 1);
  const std::pair<BelosSolver::Method, Kind> cases[] = {
      {BelosSolver::Method::cg, Kind::none},
      {BelosSolver::Method::cg, Kind::ifpack2Sgs},
      {BelosSolver::Method::cg, Kind::ifpack2Riluk},
      {BelosSolver::Method::gmres, Kind::ifpack2Ilut},
      {BelosSolver::Method::cg, Kind::muelu}};
  const char* names[] = {"cg", "cg+sgs", "cg+riluk", "gmres+ilut", "cg+muelu"};
  for (int k = 0; k < 5; ++k) {
    BelosSolver::Options o;
    o.method = cases[k].first;
    o.preconditioner.kind = cases[k].second;
    o.tolerance = 1e-10;
    BelosSolver solver(o, comm);
    MultiVector x(A->getDomainMap(), 1);
    const auto& s = solveOnce(solver, A, *b, x);
    if (comm->getRank() == 0)
      std::printf(
          "Belos %-10s %lld unknowns, %d ranks: %4d iterations, setup %.2f s, "
          "solve %.2f s\n",
          names[k], static_cast<long long>(A->getGlobalNumRows()), comm->getSize(), s.iterations,
          s.factorizationSeconds, s.solveSeconds);
  }
}

}  // namespace
}  // namespace contactlab
