// Single-precision factors refined in double (MumpsSolver's Precision, IterativeRefinement): a
// solve reaches the backward error of a direct solve in double, through corrections too; a
// matrix whose single factors fail is factorized in double, and the solver stays there;
// automatic keeps double below its flop threshold. IterativeRefinement alone: GMRES refines a
// poor approximate inverse to the target, and says so when its budget is too short.
#include "LinearTestProblems.hpp"

#include "linear/IterativeRefinement.hpp"
#include "linear/MumpsSolver.hpp"

#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>

namespace contactlab {
namespace {

using test::Layout;
using Mode = MumpsSolver::Mode;
using Precision = MumpsSolver::Precision;

Teuchos::RCP<const Comm> world() {
  return Tpetra::getDefaultComm();
}

MumpsSolver::Options options(Mode mode, Precision precision, bool reuse = true) {
  MumpsSolver::Options o;
  o.mode = mode;
  o.precision = precision;
  o.reuseFactorization = reuse;
  return o;
}

// M^-1 = D^-1, D the diagonal of A: far from A^-1 on a Laplacian (cond(D^-1 A) ~ n^2).
std::function<void(const MultiVector&, MultiVector&)> jacobi(const Matrix& A) {
  auto diagonal = Teuchos::rcp(new Vector(A.getRowMap()));
  A.getLocalDiagCopy(*diagonal);
  diagonal->reciprocal(*diagonal);
  return [diagonal](const MultiVector& in, MultiVector& out) {
    out.elementWiseMultiply(1.0, *diagonal, in, 0.0);
  };
}

TEST(IterativeRefinement, GmresRefinesAPoorApproximateInverseToTheTarget) {
  const auto A = test::convectionDiffusion(30, 5.0, Layout::scattered, world());
  const auto b = test::rightHandSide(*A, 2);
  MultiVector x(A->getDomainMap(), 2);
  RefinementOptions o;
  o.maxApplications = 400;
  o.restart = 40;
  const auto result = refineSolution(*A, normInf(*A), *b, x, jacobi(*A), o);
  EXPECT_TRUE(result.converged);
  EXPECT_LE(result.backwardError, o.backwardErrorTarget);
  EXPECT_LE(test::backwardError(*A, *b, x), o.backwardErrorTarget);
  EXPECT_GT(result.applications, 2 * 10);  // Jacobi alone is far from enough
  EXPECT_LE(result.applications, 2 * o.maxApplications);

  // The same with too short a budget: the best iterate, and the failure said.
  MultiVector y(A->getDomainMap(), 2);
  o.maxApplications = 5;
  const auto short_ = refineSolution(*A, normInf(*A), *b, y, jacobi(*A), o);
  EXPECT_FALSE(short_.converged);
  EXPECT_GT(short_.backwardError, o.backwardErrorTarget);
  EXPECT_LE(short_.applications, 2 * 5);
}

TEST(IterativeRefinement, AnExactInverseNeedsOneApplication) {
  const auto A = test::laplacian3D(10, Layout::contiguous, world());
  const auto b = test::rightHandSide(*A, 1);
  MumpsSolver direct(options(Mode::symmetricIndefinite, Precision::doublePrecision), world());
  direct.setMatrix(A, false);
  MultiVector x(A->getDomainMap(), 1);
  const auto result =
      refineSolution(*A, normInf(*A), *b, x,
                     [&](const MultiVector& in, MultiVector& out) { direct.solve(in, out); }, {});
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.applications, 1);
}

class SinglePrecisionFactors : public ::testing::TestWithParam<Mode> {};

// A 3D Laplacian (cond ~ 1e3) and a non-symmetric variant: single factors, refined solves as
// accurate as a direct solve in double; then a few changed rows through a correction of the
// single factors, refined the same way.
TEST_P(SinglePrecisionFactors, SolvesReachTheBackwardErrorOfADirectSolveInDouble) {
  const Mode mode = GetParam();
  const auto A0 = mode == Mode::general
                      ? test::convectionDiffusion(60, 3.0, Layout::scattered, world())
                      : test::laplacian3D(16, Layout::scattered, world());
  const auto b = test::rightHandSide(*A0, 2);
  MumpsSolver solver(options(mode, Precision::singlePrecision), world());
  const auto x = test::solved(solver, A0, *b);
  EXPECT_TRUE(solver.singlePrecisionFactors());
  EXPECT_EQ(solver.stats().singlePrecisionFactorizations, 1);
  EXPECT_EQ(solver.stats().doublePrecisionFallbacks, 0);
  EXPECT_GT(solver.stats().refinementSteps, 0);  // a single solve alone is ~1e-8 off
  EXPECT_LT(test::backwardError(*A0, *b, *x), 1e-13);
  MumpsSolver direct(options(mode, Precision::doublePrecision), world());
  EXPECT_FALSE(test::solved(direct, A0, *b).is_null());
  EXPECT_FALSE(direct.singlePrecisionFactors());
  EXPECT_LT(test::relativeDifference(*x, *test::solved(direct, A0, *b)), 1e-11);
}

INSTANTIATE_TEST_SUITE_P(BothModes, SinglePrecisionFactors,
                         ::testing::Values(Mode::general, Mode::symmetricIndefinite));

// The single-precision MUMPS must be the same build as the double one: Trilinos' Amesos also
// loads Debian's PORD-only libsmumps, and where it came first in the process's search order
// `smumps_c` resolved to it, so that single factors were ordered by PORD while double ones had
// SCOTCH (INFOG(7) says which ordering was used).
TEST(SinglePrecisionFactors, AreOrderedAsTheDoubleOnes) {
  const auto A = test::laplacian3D(18, Layout::scattered, world());
  const auto b = test::rightHandSide(*A, 1);
  MumpsSolver single(options(Mode::symmetricIndefinite, Precision::singlePrecision), world());
  MumpsSolver dbl(options(Mode::symmetricIndefinite, Precision::doublePrecision), world());
  EXPECT_FALSE(test::solved(single, A, *b).is_null());
  EXPECT_FALSE(test::solved(dbl, A, *b).is_null());
  ASSERT_TRUE(single.singlePrecisionFactors());
  ASSERT_TRUE(single.orderingUsed().has_value() && dbl.orderingUsed().has_value());
  EXPECT_EQ(*single.orderingUsed(), *dbl.orderingUsed());
  if (MumpsSolver::hasScotch()) {
    EXPECT_EQ(*single.orderingUsed(), MumpsSolver::Ordering::scotch);
  }
}

// Precision automatic analyses in double first (its flop count decides for single): the single
// analysis then takes the double's pivot order rather than ordering the pattern again, and the
// refined solve is as accurate as the double's.
TEST(SinglePrecisionFactors, AutomaticTakesTheDoubleAnalysisPivotOrder) {
  const auto A = test::laplacian3D(36, Layout::scattered, world());
  const auto b = test::rightHandSide(*A, 1);
  MumpsSolver solver(options(Mode::symmetricIndefinite, Precision::automatic), world());
  const auto x = test::solved(solver, A, *b);
  ASSERT_TRUE(solver.singlePrecisionFactors());  // above the flop threshold
  EXPECT_EQ(solver.stats().analyses, 2);         // double (the count), then single
  ASSERT_TRUE(solver.orderingUsed().has_value());
  if (MumpsSolver::hasScotch()) {
    EXPECT_EQ(*solver.orderingUsed(), MumpsSolver::Ordering::scotch);
  }
  EXPECT_LT(test::backwardError(*A, *b, *x), 1e-13);
}

// Springs on a few rows of a Laplacian large enough for a correction to pay: solved through a
// low-rank correction of the single factors, refined to the same backward error.
TEST(SinglePrecisionFactors, CorrectionsOfSingleFactorsAreRefined) {
  const auto base = test::laplacian3D(18, Layout::scattered, world());
  const auto sprung = test::modifiedCopy(
      *base, Layout::scattered, [](GO row, std::vector<GO>& cols, std::vector<double>& vals) {
        for (const GO p : {GO(5), GO(1000), GO(2500)})
          if (row == p) {
            cols.push_back(row);
            vals.push_back(1e4);
          }
      });
  const auto b = test::rightHandSide(*base, 1);
  MumpsSolver solver(options(Mode::symmetricIndefinite, Precision::singlePrecision), world());
  test::solved(solver, base, *b);
  const auto x = test::solved(solver, sprung, *b);
  EXPECT_EQ(solver.stats().factorizations, 1);
  EXPECT_EQ(solver.stats().corrections, 1);
  EXPECT_LT(test::backwardError(*sprung, *b, *x), 1e-13);
}

// 2 x 2 blocks [1 1; 1 1 + 1e-9] are singular once rounded to single precision (1 + 1e-9 is 1):
// the single factorization meets a zero pivot, the matrix is factorized in double, which solves
// it, and the solver stays in double for the next matrix.
TEST(SinglePrecisionFactors, AZeroPivotInSinglePrecisionFallsBackToDouble) {
  const GO size = 400;
  const auto nearlySingular = [&](double epsilon) {
    return test::makeMatrix(size, Layout::scattered, world(),
                            [=](GO row, std::vector<GO>& cols, std::vector<double>& vals) {
                              const GO first = row - row % 2;
                              cols = {first, first + 1};
                              vals = {1.0, row == first ? 1.0 : 1.0 + epsilon};
                            });
  };
  const auto A = nearlySingular(1e-9);
  const auto b = test::rightHandSide(*A, 1);
  MumpsSolver solver(options(Mode::general, Precision::singlePrecision, false), world());
  const auto x = test::solved(solver, A, *b);
  EXPECT_EQ(solver.stats().doublePrecisionFallbacks, 1);
  EXPECT_EQ(solver.stats().singlePrecisionFactorizations, 0);
  EXPECT_FALSE(solver.singlePrecisionFactors());
  EXPECT_LT(test::backwardError(*A, *b, *x), 1e-13);
  test::solved(solver, nearlySingular(1e-3), *b);
  EXPECT_FALSE(solver.singlePrecisionFactors());
  EXPECT_EQ(solver.stats().factorizations, 2);
}

// Below kSingleFactorizationFlops, automatic is double: the regression gold's small models keep
// one direct solve per right-hand side, and their round-off.
TEST(SinglePrecisionFactors, AutomaticKeepsDoubleForASmallMatrix) {
  const auto A = test::laplacian3D(12, Layout::contiguous, world());
  const auto b = test::rightHandSide(*A, 1);
  MumpsSolver solver(options(Mode::symmetricIndefinite, Precision::automatic), world());
  test::solved(solver, A, *b);
  EXPECT_FALSE(solver.singlePrecisionFactors());
  EXPECT_EQ(solver.stats().refinementSteps, 0);
  // A determinant is asked of double factors even when single is asked for.
  MumpsSolver::Options o = options(Mode::symmetricIndefinite, Precision::singlePrecision);
  o.determinant = true;
  MumpsSolver withDeterminant(o, world());
  test::solved(withDeterminant, A, *b);
  EXPECT_FALSE(withDeterminant.singlePrecisionFactors());
  EXPECT_TRUE(withDeterminant.determinant().has_value());
}

}  // namespace
}  // namespace contactlab
