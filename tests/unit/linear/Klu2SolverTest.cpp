// Klu2Solver: correct on any number of ranks and map layout (gathered to rank 0), residual guard.
#include "LinearTestProblems.hpp"

#include "linear/Klu2Solver.hpp"
#include "linear/MumpsSolver.hpp"

#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>

namespace contactlab {
namespace {

using test::Layout;

Teuchos::RCP<const Comm> world() {
  return Tpetra::getDefaultComm();
}

class Klu2Layouts : public ::testing::TestWithParam<Layout> {};

TEST_P(Klu2Layouts, AgreesWithMumpsOnANonSymmetricMatrix) {
  const auto A = test::convectionDiffusion(25, 2.0, GetParam(), world());
  for (size_t columns : {1, 3}) {  // Amesos2 has separate one- and many-column paths
    const auto b = test::rightHandSide(*A, columns);
    Klu2Solver klu({}, world());
    klu.setMatrix(A, true);
    MultiVector x(A->getDomainMap(), columns);
    klu.solve(*b, x);
    EXPECT_LT(klu.stats().relativeResidual, 1e-12);
    EXPECT_LT(test::relativeResidual(*A, *b, x), 1e-12);
    MumpsSolver mumps({}, world());
    mumps.setMatrix(A, true);
    MultiVector y(A->getDomainMap(), columns);
    mumps.solve(*b, y);
    EXPECT_LT(test::relativeDifference(x, y), 1e-10);
  }
}

TEST_P(Klu2Layouts, ReusesTheAnalysisWhenOnlyValuesChange) {
  auto A = test::saddlePoint(12, 10, GetParam(), world());
  const auto b = test::rightHandSide(*A, 2);
  Klu2Solver klu({}, world());
  klu.setMatrix(A, true);
  MultiVector x1(A->getDomainMap(), 2), x2(A->getDomainMap(), 2);
  klu.solve(*b, x1);
  A->resumeFill();
  A->scale(-4.0);
  A->fillComplete();
  klu.setMatrix(A, false);
  klu.solve(*b, x2);
  EXPECT_EQ(klu.stats().analyses, 1);
  EXPECT_EQ(klu.stats().factorizations, 2);
  EXPECT_EQ(klu.stats().solves, 2);
  x2.scale(-4.0);
  EXPECT_LT(test::relativeDifference(x2, x1), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(BothLayouts, Klu2Layouts,
                         ::testing::Values(Layout::contiguous, Layout::scattered));

TEST(Klu2Solver, ResidualGuardThrowsRatherThanReturnAnInaccurateAnswer) {
  Klu2Solver::Options o;
  o.residualTolerance = 1e-30;  // round-off alone exceeds it
  const auto A = test::laplacian2D(15, 15, Layout::scattered, world());
  Klu2Solver klu(o, world());
  klu.setMatrix(A, true);
  MultiVector x(A->getDomainMap(), 1);
  try {
    klu.solve(*test::rightHandSide(*A, 1), x);
    ADD_FAILURE() << "no error";
  } catch (const LinearSolverError& e) {
    EXPECT_NE(std::string(e.what()).find("relative residual"), std::string::npos) << e.what();
  }
}

TEST(Klu2Solver, SingularMatrixThrowsOnEveryRank) {
  const auto A = test::makeMatrix(8, Layout::scattered, world(), [](GO g, auto& c, auto& v) {
    if (g == 2 || g == 5) {
      c = {2, 5};
      v = {1.0, 3.0};
    } else {
      c = {g};
      v = {1.0};
    }
  });
  Klu2Solver klu({}, world());
  try {
    klu.setMatrix(A, true);
    ADD_FAILURE() << "no error";
  } catch (const LinearSolverError& e) {
    EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace contactlab
