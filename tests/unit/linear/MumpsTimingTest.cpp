// Sanity timings, not run by default (a few seconds to a minute). Run with
//   mpirun -np 2 unit_linear --gtest_also_run_disabled_tests --gtest_filter='*Timing*'
// Size from CONTACTLAB_TIMING_N (grid points per direction, default 46: 97 336 unknowns).
#include <cstdio>
#include <cstdlib>

#include <gtest/gtest.h>
#include <Tpetra_Core.hpp>

#include "LinearTestProblems.hpp"
#include "linear/MumpsSolver.hpp"

namespace contactlab {
namespace {

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
    solver.setMatrix(A, true);
    MultiVector x(A->getDomainMap(), 1);
    solver.solve(*b, x);
    const auto& s = solver.stats();
    if (comm->getRank() == 0)
      std::printf("MUMPS %s, %lld unknowns, %d ranks: analysis %.2f s, factorization %.2f s, "
                  "solve %.3f s\n",
                  mode == MumpsSolver::Mode::general ? "general  " : "symmetric",
                  static_cast<long long>(A->getGlobalNumRows()), comm->getSize(),
                  s.analysisSeconds, s.factorizationSeconds, s.solveSeconds);
    EXPECT_LT(test::relativeResidual(*A, *b, x), 1e-10);
  }
}

}  // namespace
}  // namespace contactlab
