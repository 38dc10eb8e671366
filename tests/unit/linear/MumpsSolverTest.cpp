// MumpsSolver: solutions in each mode, analysis reuse, determinant (mantissa/exponent, sign,
// rank-independence), condition estimate, inertia and errors.
#include "LinearTestProblems.hpp"

#include "linear/MumpsSolver.hpp"

#include <Tpetra_Core.hpp>

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

using test::Layout;
using Mode = MumpsSolver::Mode;

Teuchos::RCP<const Comm> world() {
  return Tpetra::getDefaultComm();
}

MumpsSolver::Options optionsWith(Mode mode, bool determinant = false) {
  MumpsSolver::Options o;
  o.mode = mode;
  o.determinant = determinant;
  return o;
}

// Solves A x = b (3 right-hand sides) and returns x.
Teuchos::RCP<MultiVector> solveWith(LinearSolver& solver, const Teuchos::RCP<Matrix>& A,
                                    const MultiVector& b) {
  solver.setMatrix(A, true);
  auto x = Teuchos::rcp(new MultiVector(A->getDomainMap(), b.getNumVectors()));
  solver.solve(b, *x);
  return x;
}

struct ModeCase {
  const char* problem;
  Mode mode;
  Layout layout;
};

class MumpsModes : public ::testing::TestWithParam<ModeCase> {};

Teuchos::RCP<Matrix> problemMatrix(const std::string& name, Layout layout) {
  if (name == "laplacian2d") return test::laplacian2D(23, 17, layout, world());
  if (name == "laplacian3d") return test::laplacian3D(9, layout, world());
  if (name == "saddle") return test::saddlePoint(15, 12, layout, world());
  return test::convectionDiffusion(20, 3.0, layout, world());
}

TEST_P(MumpsModes, SolvesWithSmallResidualAndAgreesWithGeneralMode) {
  const auto& c = GetParam();
  const auto A = problemMatrix(c.problem, c.layout);
  const auto b = test::rightHandSide(*A, 3);
  MumpsSolver solver(optionsWith(c.mode), world());
  const auto x = solveWith(solver, A, *b);
  EXPECT_LT(test::relativeResidual(*A, *b, *x), 1e-12);
  // Reference: general mode on the contiguous layout.
  const auto Aref = problemMatrix(c.problem, Layout::contiguous);
  MumpsSolver reference(optionsWith(Mode::general), world());
  const auto xref = solveWith(reference, Aref, *test::rightHandSide(*Aref, 3));
  EXPECT_LT(test::relativeDifference(*x, *xref), 1e-10);
  EXPECT_EQ(solver.stats().analyses, 1);
  EXPECT_EQ(solver.stats().factorizations, 1);
  EXPECT_EQ(solver.stats().solves, 1);
}

INSTANTIATE_TEST_SUITE_P(
    AllModes, MumpsModes,
    ::testing::Values(ModeCase{"laplacian2d", Mode::general, Layout::contiguous},
                      ModeCase{"laplacian2d", Mode::symmetric, Layout::scattered},
                      ModeCase{"laplacian3d", Mode::symmetric, Layout::contiguous},
                      ModeCase{"laplacian3d", Mode::symmetricIndefinite, Layout::scattered},
                      ModeCase{"saddle", Mode::general, Layout::scattered},
                      ModeCase{"saddle", Mode::symmetricIndefinite, Layout::contiguous},
                      ModeCase{"saddle", Mode::symmetricIndefinite, Layout::scattered},
                      ModeCase{"convdiff", Mode::general, Layout::contiguous},
                      ModeCase{"convdiff", Mode::general, Layout::scattered}));

TEST(MumpsSolver, ReusesTheAnalysisWhenOnlyValuesChange) {
  auto A = test::laplacian2D(20, 20, Layout::scattered, world());
  const auto b = test::rightHandSide(*A, 1);
  MumpsSolver solver(optionsWith(Mode::symmetric), world());
  const auto x1 = solveWith(solver, A, *b);
  A->resumeFill();
  A->scale(2.0);
  A->fillComplete();
  solver.setMatrix(A, false);
  MultiVector x2(A->getDomainMap(), 1);
  solver.solve(*b, x2);
  EXPECT_EQ(solver.stats().analyses, 1);
  EXPECT_EQ(solver.stats().factorizations, 2);
  x2.scale(2.0);  // (2A)^-1 b = x1 / 2
  EXPECT_LT(test::relativeDifference(x2, *x1), 1e-12);
}

// A symmetric mode told that the matrices may no longer be symmetric (the geometry retry's
// full terms, StaticSolver) solves an unsymmetric matrix exactly, where it read the lower
// triangle before; it analyses again and says it assumes nothing.
TEST(MumpsSolver, TakesAnyMatrixOnceTold) {
  const auto S = test::laplacian2D(15, 12, Layout::scattered, world());
  const auto U = test::convectionDiffusion(20, 3.0, Layout::scattered, world());
  const auto bS = test::rightHandSide(*S, 2), bU = test::rightHandSide(*U, 2);
  MumpsSolver solver(optionsWith(Mode::symmetricIndefinite), world());
  EXPECT_FALSE(solver.symmetryAssumption().empty());
  EXPECT_LT(test::relativeResidual(*S, *bS, *solveWith(solver, S, *bS)), 1e-12);
  EXPECT_GT(test::relativeResidual(*U, *bU, *solveWith(solver, U, *bU)), 1e-6);  // lower only
  solver.takeAnyMatrix();
  EXPECT_TRUE(solver.symmetryAssumption().empty());
  EXPECT_LT(test::relativeResidual(*U, *bU, *solveWith(solver, U, *bU)), 1e-12);
  EXPECT_LT(test::relativeResidual(*S, *bS, *solveWith(solver, S, *bS)), 1e-12);
  EXPECT_EQ(solver.stats().analyses, 4);
  EXPECT_FALSE(solver.negativePivots().has_value());  // general mode: no inertia
}

// MUMPS falls back to another ordering without a word when the one asked for is not built in
// (Debian's libmumps-dev has PORD only): the automatic choice must be the one INFOG(7) reports,
// SCOTCH with libmumps-ptscotch from 5 000 unknowns (here 18^3), and every ordering must solve
// the same system.
TEST(MumpsSolver, TheAutomaticOrderingIsTheOneMumpsUses) {
  using Ordering = MumpsSolver::Ordering;
  auto A = test::laplacian3D(18, Layout::scattered, world());
  const auto b = test::rightHandSide(*A, 1);
  MumpsSolver::Options automatic = optionsWith(Mode::symmetric);
  MumpsSolver solver(automatic, world());
  EXPECT_FALSE(solver.orderingUsed().has_value());
  const auto x = solveWith(solver, A, *b);
  ASSERT_TRUE(solver.orderingUsed().has_value());
  EXPECT_EQ(*solver.orderingUsed(), MumpsSolver::hasScotch() ? Ordering::scotch : Ordering::pord);
  for (Ordering o : {Ordering::pord, Ordering::amd, Ordering::scotch}) {
    if (o == Ordering::scotch && !MumpsSolver::hasScotch()) continue;
    MumpsSolver::Options options = automatic;
    options.ordering = o;
    MumpsSolver other(options, world());
    const auto y = solveWith(other, A, *b);
    EXPECT_EQ(*other.orderingUsed(), o);
    EXPECT_LT(test::relativeDifference(*y, *x), 1e-12);
  }
  // SCOTCH orders with a thread per core unless told otherwise: the same matrix must get
  // the same ordering, so the same solution to the last bit, in every solver and every run. On
  // one rank only: on several, MUMPS' dynamic scheduling of the factorization between the
  // processes already varies the last bits from run to run, whatever the ordering.
  if (MumpsSolver::hasScotch() && world()->getSize() == 1) {
    MumpsSolver again(automatic, world());
    const auto y = solveWith(again, A, *b);
    EXPECT_EQ(test::relativeDifference(*y, *x), 0.0);
  }
}

// An equal pattern keeps its analysis even when the caller says it may have changed (a study's
// next run builds a new matrix of the same pattern), and the solution is the same: the analysis
// of a distributed matrix reads the pattern only.
TEST(MumpsSolver, KeepsTheAnalysisOfAnEqualPatternToldAsChanged) {
  // Without factorization reuse, which would find the copy equal and factorize nothing.
  auto options = optionsWith(Mode::general);
  options.reuseFactorization = false;
  MumpsSolver solver(options, world());
  const auto A = test::convectionDiffusion(10, 1.0, Layout::contiguous, world());
  const auto b = test::rightHandSide(*A, 1);
  MultiVector first(A->getDomainMap(), 1);
  solver.setMatrix(A, true);
  solver.solve(*b, first);
  const auto again = test::convectionDiffusion(10, 1.0, Layout::contiguous, world());  // a copy
  solver.setMatrix(again, true);
  MultiVector second(A->getDomainMap(), 1);
  solver.solve(*b, second);
  EXPECT_EQ(solver.stats().analyses, 1);
  EXPECT_EQ(solver.stats().factorizations, 2);
  // Bitwise on one rank; on several, MUMPS' dynamic scheduling between the processes varies
  // the last bits from one factorization to the next (see above).
  EXPECT_LE(test::relativeDifference(second, first), world()->getSize() == 1 ? 0.0 : 1e-12);
}

TEST(MumpsSolver, AnalysesAgainWhenThePatternChangedEvenIfNotTold) {
  MumpsSolver solver(optionsWith(Mode::general), world());
  solver.setMatrix(test::laplacian2D(10, 10, Layout::contiguous, world()), true);
  const auto B = test::convectionDiffusion(10, 1.0, Layout::contiguous, world());  // same n
  const auto C = test::tridiagonal(100, Layout::contiguous, world());              // other pattern
  solver.setMatrix(C, false);
  EXPECT_EQ(solver.stats().analyses, 2);
  const auto b = test::rightHandSide(*C, 1);
  MultiVector x(C->getDomainMap(), 1);
  solver.solve(*b, x);
  EXPECT_LT(test::relativeResidual(*C, *b, x), 1e-12);
  solver.setMatrix(B, false);  // the Laplacian's pattern again, but not the analysed one
  EXPECT_EQ(solver.stats().analyses, 3);
}

// det = mantissa * 2^exponent as a long double-free comparison: log2 |det|.
double log2Abs(const Determinant& d) {
  return std::log2(std::fabs(d.mantissa)) + d.exponent;
}

class MumpsDeterminant : public ::testing::TestWithParam<Mode> {};

TEST_P(MumpsDeterminant, OfTridiagonalIsNPlusOne) {
  const GO n = 10000;
  MumpsSolver solver(optionsWith(GetParam(), true), world());
  solver.setMatrix(test::tridiagonal(n, Layout::scattered, world()), true);
  const auto det = solver.determinant();
  ASSERT_TRUE(det.has_value());
  EXPECT_GE(std::fabs(det->mantissa), 0.5);
  EXPECT_LT(std::fabs(det->mantissa), 1.0);
  EXPECT_NEAR(std::ldexp(det->mantissa, static_cast<int>(det->exponent)), n + 1.0, 1e-8 * n);
  EXPECT_EQ(det->sign(), 1);
}

TEST_P(MumpsDeterminant, OfDiagTwoOfOrder3000OverflowsDoubleButNotTheMantissa) {
  MumpsSolver solver(optionsWith(GetParam(), true), world());
  solver.setMatrix(test::diagonal(
                       3000, [](GO) { return 2.0; }, Layout::scattered, world()),
                   true);
  const auto det = solver.determinant();  // 2^3000 = 0.5 * 2^3001
  ASSERT_TRUE(det.has_value());
  EXPECT_EQ(det->exponent, 3001);
  EXPECT_NEAR(det->mantissa, 0.5, 1e-12);
  EXPECT_NEAR(det->log10Abs(), 3000 * std::log10(2.0), 1e-9);
}

TEST_P(MumpsDeterminant, OfHugeDiagonal) {
  MumpsSolver solver(optionsWith(GetParam(), true), world());
  solver.setMatrix(test::diagonal(
                       50, [](GO) { return 1e300; }, Layout::contiguous, world()),
                   true);
  const auto det = solver.determinant();
  ASSERT_TRUE(det.has_value());
  EXPECT_NEAR(det->log10Abs(), 15000.0, 1e-8);
  EXPECT_EQ(det->sign(), 1);
}

INSTANTIATE_TEST_SUITE_P(AllModes, MumpsDeterminant,
                         ::testing::Values(Mode::general, Mode::symmetric,
                                           Mode::symmetricIndefinite));

TEST(MumpsSolver, DeterminantSignAndInertiaOfAnIndefiniteDiagonal) {
  const GO n = 301;
  const auto d = [](GO g) { return g % 3 == 0 ? -1.5 : 2.0 + 0.01 * g; };
  int negatives = 0;
  double log2Exact = 0;
  for (GO g = 0; g < n; ++g) {
    negatives += d(g) < 0;
    log2Exact += std::log2(std::fabs(d(g)));
  }
  for (Mode mode : {Mode::general, Mode::symmetricIndefinite}) {
    MumpsSolver solver(optionsWith(mode, true), world());
    solver.setMatrix(test::diagonal(n, d, Layout::scattered, world()), true);
    const auto det = solver.determinant();
    ASSERT_TRUE(det.has_value());
    EXPECT_EQ(det->sign(), negatives % 2 ? -1 : 1);
    EXPECT_NEAR(log2Abs(*det), log2Exact, 1e-9 * log2Exact);
    if (mode == Mode::symmetricIndefinite) {
      ASSERT_TRUE(solver.negativePivots().has_value());
      EXPECT_EQ(*solver.negativePivots(), negatives);
    }
  }
}

TEST(MumpsSolver, InertiaOfSaddlePointCountsTheConstraints) {
  MumpsSolver solver(optionsWith(Mode::symmetricIndefinite, true), world());
  solver.setMatrix(test::saddlePoint(15, 12, Layout::scattered, world()), true);
  EXPECT_EQ(solver.negativePivots().value(), 12);
  EXPECT_EQ(solver.determinant()->sign(), 1);  // (-1)^12
}

TEST(MumpsSolver, DeterminantIsTheSameOnAllRanksAndOnOneRank) {
  // The same matrix factorized by all ranks and by each rank alone.
  const auto selfComm = world()->split(world()->getRank(), 0);
  Determinant dets[2];
  for (int k = 0; k < 2; ++k) {
    const auto comm = k == 0 ? world() : Teuchos::RCP<const Comm>(selfComm);
    MumpsSolver solver(optionsWith(Mode::symmetricIndefinite, true), comm);
    solver.setMatrix(test::saddlePoint(20, 9, Layout::scattered, comm), true);
    dets[k] = *solver.determinant();
  }
  EXPECT_EQ(dets[0].sign(), dets[1].sign());
  EXPECT_NEAR(log2Abs(dets[0]), log2Abs(dets[1]), 1e-12 * std::fabs(log2Abs(dets[1])));
}

TEST(MumpsSolver, NoDeterminantUnlessRequested) {
  MumpsSolver solver(optionsWith(Mode::general), world());
  solver.setMatrix(test::tridiagonal(10, Layout::contiguous, world()), true);
  EXPECT_FALSE(solver.determinant().has_value());
  EXPECT_FALSE(solver.conditionEstimate().has_value());
}

TEST(MumpsSolver, ConditionEstimateGrowsWithIllConditioning) {
  MumpsSolver::Options o;
  o.conditionEstimate = true;
  double estimates[2];
  const int sizes[2] = {5, 60};
  for (int k = 0; k < 2; ++k) {
    const auto A = test::laplacian2D(sizes[k], sizes[k], Layout::scattered, world());
    MumpsSolver solver(o, world());
    EXPECT_FALSE(solver.conditionEstimate().has_value());
    const auto b = test::rightHandSide(*A, 2);
    const auto x = solveWith(solver, A, *b);
    EXPECT_LT(test::relativeResidual(*A, *b, *x), 1e-12);  // both columns solved
    ASSERT_TRUE(solver.conditionEstimate().has_value());
    estimates[k] = *solver.conditionEstimate();
    const auto analysis = solver.errorAnalysis().value();
    EXPECT_LT(analysis.omega1, 1e-14);
    EXPECT_GE(estimates[k], 1.0);
  }
  EXPECT_GT(estimates[1], estimates[0]);
}

TEST(MumpsSolver, SingularMatrixThrowsNamingSingularity) {
  // Rows 3 and 4 are equal: exactly singular in any pivot order.
  const auto A = test::makeMatrix(10, Layout::scattered, world(), [](GO g, auto& c, auto& v) {
    if (g == 3 || g == 4) {
      c = {3, 4};
      v = {1.0, 1.0};
    } else {
      c = {g};
      v = {2.0};
    }
  });
  for (Mode mode : {Mode::general, Mode::symmetricIndefinite}) {
    MumpsSolver solver(optionsWith(mode), world());
    try {
      solver.setMatrix(A, true);
      ADD_FAILURE() << "no error for a singular matrix";
    } catch (const SingularMatrixError& e) {  // typed: the algorithms name it for the model
      EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("INFOG(1) = -"), std::string::npos) << e.what();
    } catch (const LinearSolverError& e) {
      ADD_FAILURE() << "not a SingularMatrixError: " << e.what();
    }
  }
}

TEST(MumpsSolver, ARoundOffPivotIsProvedSingularByTheSolution) {
  // Rows 3 and 4 differ by round-off: MUMPS factors it, and x is of order 1 / eps.
  const auto A = test::makeMatrix(10, Layout::scattered, world(), [](GO g, auto& c, auto& v) {
    if (g == 3 || g == 4) {
      c = {3, 4};
      v = {1.0, g == 4 ? 1.0 + 4e-16 : 1.0};
    } else {
      c = {g};
      v = {2.0};
    }
  });
  const auto b = test::rightHandSide(*A, 1);
  b->putScalar(1.0);
  if (b->getMap()->isNodeGlobalElement(4))  // inconsistent with row 3 but for round-off
    b->replaceGlobalValue(4, 0, 2.0);
  MumpsSolver solver(optionsWith(Mode::general), world());
  const auto x = solveWith(solver, A, *b);
  EXPECT_GT(conditionLowerBound(*A, *b, *x), kSingularConditionBound);
  EXPECT_THROW(throwIfNumericallySingular(*A, *b, *x), SingularMatrixError);
  // A regular matrix passes, however the right-hand side.
  const auto L = test::laplacian2D(23, 17, Layout::scattered, world());
  const auto bL = test::rightHandSide(*L, 3);
  const auto xL = solveWith(solver, L, *bL);
  EXPECT_LT(conditionLowerBound(*L, *bL, *xL), 1e4);
  EXPECT_NO_THROW(throwIfNumericallySingular(*L, *bL, *xL));
  // A regular matrix whose rows are in units 1e16 apart (a stiff block beside a soft one,
  // multiplier rows beside displacement rows) passes: the bound is taken on the scaled rows.
  const auto S = test::makeMatrix(10, Layout::scattered, world(), [](GO g, auto& c, auto& v) {
    c = {g};
    v = {g % 2 ? 1e8 : 1e-8};
  });
  const auto bS = test::rightHandSide(*S, 1);
  bS->putScalar(1.0);
  const auto xS = solveWith(solver, S, *bS);
  EXPECT_LT(conditionLowerBound(*S, *bS, *xS), 10.0);
  EXPECT_NO_THROW(throwIfNumericallySingular(*S, *bS, *xS));
}

TEST(MumpsSolver, PositiveDefiniteModeOnAnIndefiniteMatrixSuggestsTheIndefiniteMode) {
  MumpsSolver solver(optionsWith(Mode::symmetric), world());
  try {
    solver.setMatrix(test::saddlePoint(15, 12, Layout::scattered, world()), true);
    ADD_FAILURE() << "no error";
  } catch (const LinearSolverError& e) {
    EXPECT_NE(std::string(e.what()).find("symmetric-indefinite"), std::string::npos) << e.what();
  }
}

TEST(MumpsSolver, RejectsGlobalIdsOutsideZeroToN) {
  // Rows 10..19: N = 10 but the ids are not in [0, 10).
  const auto comm = world();
  const auto map = Teuchos::rcp(new Map(10, GO(10), comm));
  auto A = Teuchos::rcp(new Matrix(map, 1));
  for (GO g : map->getNodeElementList())
    A->insertGlobalValues(g, Teuchos::tuple<GO>(g), Teuchos::tuple<double>(1.0));
  A->fillComplete();
  MumpsSolver solver(optionsWith(Mode::general), comm);
  EXPECT_THROW(solver.setMatrix(A, true), LinearSolverError);
}

TEST(MumpsSolver, SolveBeforeSetMatrixThrows) {
  MumpsSolver solver(optionsWith(Mode::general), world());
  const auto A = test::tridiagonal(5, Layout::contiguous, world());
  MultiVector x(A->getDomainMap(), 1);
  EXPECT_THROW(solver.solve(*test::rightHandSide(*A, 1), x), LinearSolverError);
}

TEST(MumpsSolver, RaisesTheMemoryRelaxationOnceWhenWorkspaceRunsOut) {
  // Tiny pivots force many delayed pivots: the analysis' estimate is far too small.
  const auto A = test::tinyDiagonalIndefinite(20, Layout::scattered, world());
  MumpsSolver::Options o = optionsWith(Mode::symmetricIndefinite);
  o.memoryRelaxation = 0;
  MumpsSolver solver(o, world());
  const auto b = test::rightHandSide(*A, 1);
  const auto x = solveWith(solver, A, *b);
  EXPECT_LT(test::relativeResidual(*A, *b, *x), 1e-10);
  EXPECT_GT(solver.memoryRelaxation(), 0);  // it was raised
  EXPECT_EQ(solver.stats().factorizations, 1);
}

}  // namespace
}  // namespace contactlab
