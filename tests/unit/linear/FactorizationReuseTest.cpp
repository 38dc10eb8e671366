// MumpsSolver's factorization reuse: a matrix equal to the factorized one costs no
// factorization; one that differs on a few rows and columns is solved through the low-rank
// correction (CapacitanceCorrection) to the accuracy of a direct solve, in both MUMPS modes and
// with a changed pattern; a matrix that changed everywhere is factorized. MatrixSnapshot's
// difference is checked entry by entry.
#include "LinearTestProblems.hpp"

#include "linear/MatrixSnapshot.hpp"
#include "linear/MumpsSolver.hpp"

#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>

namespace contactlab {
namespace {

using test::Layout;
using Mode = MumpsSolver::Mode;

Teuchos::RCP<const Comm> world() {
  return Tpetra::getDefaultComm();
}

constexpr int kGrid = 18;  // 5 832 unknowns: a factorization worth avoiding
constexpr GO kSize = GO(kGrid) * kGrid * kGrid;

// A "contact" term between unknowns p and q: stiffness k on (p, p), (q, q), -k on (p, q),
// (q, p) (symmetric), plus an entry (p, q + 1) that is not in the Laplacian's pattern when
// `outsidePattern`.
struct Spring {
  GO p, q;
  double k;
};

// The 7-point Laplacian on kGrid^3, plus springs, times `scale`; with `drift`, a
// non-symmetric first-order term.
Teuchos::RCP<Matrix> modelMatrix(const std::vector<Spring>& springs, Layout layout,
                                 double drift = 0.0, bool outsidePattern = false,
                                 double scale = 1.0) {
  return test::makeMatrix(
      kSize, layout, world(), [&](GO row, std::vector<GO>& cols, std::vector<double>& vals) {
        const int n = kGrid;
        const int i = static_cast<int>(row % n), j = static_cast<int>((row / n) % n),
                  k = static_cast<int>(row / (GO(n) * n));
        cols.push_back(row);
        vals.push_back(6.0 * scale);
        auto neighbour = [&](bool inside, GO col, double v) {
          if (!inside) return;
          cols.push_back(col);
          vals.push_back(v * scale);
        };
        neighbour(i > 0, row - 1, -1.0 - drift);
        neighbour(i < n - 1, row + 1, -1.0 + drift);
        neighbour(j > 0, row - n, -1.0);
        neighbour(j < n - 1, row + n, -1.0);
        neighbour(k > 0, row - GO(n) * n, -1.0);
        neighbour(k < n - 1, row + GO(n) * n, -1.0);
        for (const auto& s : springs) {
          if (row == s.p || row == s.q) {
            cols.push_back(row);
            vals.push_back(s.k);
            cols.push_back(row == s.p ? s.q : s.p);
            vals.push_back(-s.k);
          }
          if (outsidePattern && row == s.p) {
            cols.push_back(s.q + 1);
            vals.push_back(0.5 * s.k);
          }
        }
      });
}

std::vector<Spring> contactSprings(double k) {
  // Unknowns far apart in the grid: the springs couple distant rows, as contact couples
  // distant surface nodes.
  return {{5, kSize - 7, k}, {1000, 4000, 2 * k}, {2500, 2600, 0.5 * k}};
}

MumpsSolver::Options withMode(Mode mode, bool reuse = true) {
  MumpsSolver::Options o;
  o.mode = mode;
  o.reuseFactorization = reuse;
  return o;
}

TEST(MatrixSnapshot, DifferenceListsTheChangedEntriesAcrossPatterns) {
  const auto A0 = modelMatrix({}, Layout::scattered);
  const auto A = modelMatrix({{5, 40, 2.0}}, Layout::scattered, 0.0, true);
  const MatrixSnapshot snapshot(*A0);
  ASSERT_TRUE(snapshot.sameRowsAs(*A));
  const auto d = snapshot.differenceFrom(*A, kSize);
  EXPECT_FALSE(d.exceeded);
  // Rows 5 and 40 each gain 2 on the diagonal and -2 off it; row 5 also gets (5, 41) = 1.
  double sum = 0;
  for (const auto& e : d.entries) {
    EXPECT_TRUE(e.row == 5 || e.row == 40);
    sum += e.value;
  }
  const bool owns5 = A->getRowMap()->isNodeGlobalElement(5);
  const bool owns40 = A->getRowMap()->isNodeGlobalElement(40);
  EXPECT_DOUBLE_EQ(sum, (owns5 ? 1.0 : 0.0));  // (2 - 2) per row, + 1 on row 5
  EXPECT_EQ(d.entries.size(), (owns5 ? 3u : 0u) + (owns40 ? 2u : 0u));
  if (owns5) {
    EXPECT_NE(std::find(d.indices.begin(), d.indices.end(), 41), d.indices.end());
  }
  EXPECT_TRUE(snapshot.differenceFrom(*A0, kSize).entries.empty());
  // The same pattern with other values (the positional comparison): every (r, r -+ 1) entry
  // moves by -+ drift, under its global column.
  const auto drifted = modelMatrix({}, Layout::scattered, 0.25);
  const auto moved = snapshot.differenceFrom(*drifted, kSize);
  size_t expected = 0;
  for (LO r = 0; r < static_cast<LO>(A0->getNodeNumRows()); ++r) {
    const int i = static_cast<int>(A0->getRowMap()->getGlobalElement(r) % kGrid);
    expected += (i > 0 ? 1 : 0) + (i < kGrid - 1 ? 1 : 0);
  }
  EXPECT_EQ(moved.entries.size(), expected);
  for (const auto& e : moved.entries) {
    ASSERT_TRUE(e.col == e.row - 1 || e.col == e.row + 1) << e.row << ", " << e.col;
    EXPECT_DOUBLE_EQ(e.value, e.col < e.row ? -0.25 : 0.25);
  }
  // A matrix changed everywhere: the scan stops past the limit on every rank.
  const auto scaled = snapshot.differenceFrom(*modelMatrix({}, Layout::scattered, 0, false, 2), 10);
  EXPECT_TRUE(scaled.exceeded);
  EXPECT_LE(scaled.entries.size(), 11u * 7u);
}

class FactorizationReuse : public ::testing::TestWithParam<Mode> {};

TEST_P(FactorizationReuse, AFewChangedRowsAreSolvedThroughACorrection) {
  const Mode mode = GetParam();
  const double drift = mode == Mode::general ? 0.3 : 0.0;
  const bool outsidePattern = mode == Mode::general;
  const auto A0 = modelMatrix({}, Layout::scattered, drift);
  const auto b = test::rightHandSide(*A0, 2);
  MumpsSolver solver(withMode(mode), world());
  const auto x0 = test::solved(solver, A0, *b);
  EXPECT_EQ(solver.stats().factorizations, 1);

  // The same values again (a new matrix object): no factorization, the same solution.
  const auto again = test::solved(solver, modelMatrix({}, Layout::scattered, drift), *b);
  EXPECT_EQ(solver.stats().factorizations, 1);
  EXPECT_EQ(solver.stats().reusedFactorizations, 1);
  // Bitwise on one rank; on several, MUMPS' dynamic scheduling varies the last bits.
  EXPECT_LE(test::relativeDifference(*again, *x0), world()->getSize() == 1 ? 0.0 : 1e-14);

  // Springs stiffer than the matrix by 1e4 (a penalty's ratio): a correction of rank 6 (9 with
  // the entries outside the pattern, (p, q + 1)), as accurate as a factorization of A.
  for (double k : {1e4, 3e4}) {
    const auto A = modelMatrix(contactSprings(k), Layout::scattered, drift, outsidePattern);
    const auto x = test::solved(solver, A, *b);
    MumpsSolver direct(withMode(mode, false), world());
    const auto reference = test::solved(direct, A, *b);
    // The solver's promise is the backward error (kCorrectionBackwardError = 1e-13; here
    // ~3e-17). The relative residual is that times ||A|| ||x|| / ||b|| ~ 1e4: ~3e-13 usually,
    // but on 2 ranks MUMPS' dynamic scheduling gave once in 25 loaded runs a factorization
    // whose correction reached 3.5e-10 (a backward error ~3.5e-14, accepted, no refinement).
    EXPECT_LT(test::backwardError(*A, *b, *x), 1e-13);
    EXPECT_LT(test::relativeDifference(*x, *reference), 1e-10);
  }
  EXPECT_EQ(solver.stats().factorizations, 1);
  EXPECT_EQ(solver.stats().corrections, 2);
  EXPECT_EQ(solver.stats().lastCorrectionRank, outsidePattern ? 9 : 6);

  // Every row changed: factorized.
  const auto scaled = modelMatrix({}, Layout::scattered, drift, false, 2.0);
  const auto x2 = test::solved(solver, scaled, *b);
  EXPECT_EQ(solver.stats().factorizations, 2);
  x2->scale(2.0);
  EXPECT_LT(test::relativeDifference(*x2, *x0), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(BothModes, FactorizationReuse,
                         ::testing::Values(Mode::general, Mode::symmetricIndefinite));

TEST(FactorizationReuse, NeverFactorizesEveryMatrix) {
  const auto A0 = modelMatrix({}, Layout::contiguous);
  const auto b = test::rightHandSide(*A0, 1);
  MumpsSolver solver(withMode(Mode::symmetricIndefinite, false), world());
  test::solved(solver, A0, *b);
  test::solved(solver, modelMatrix({}, Layout::contiguous), *b);
  test::solved(solver, modelMatrix(contactSprings(1e4), Layout::contiguous), *b);
  EXPECT_EQ(solver.stats().factorizations, 3);
  EXPECT_EQ(solver.stats().reusedFactorizations, 0);
}

// A change that makes A singular (row and column p zeroed) cannot be solved through the
// correction: the residual check cannot tell (a zero row's residual does not depend on x), the
// condition estimate of I + G D refuses it, A is factorized, and MUMPS' zero pivot is reported
// as a singular matrix, as without reuse.
TEST(FactorizationReuse, ASingularChangeIsReportedAsWithoutReuse) {
  const auto A0 = modelMatrix({}, Layout::scattered);
  const auto b = test::rightHandSide(*A0, 1);
  MumpsSolver solver(withMode(Mode::general), world());
  test::solved(solver, A0, *b);
  const GO p = 100;
  const auto singular = test::modifiedCopy(
      *A0, Layout::scattered, [&](GO row, std::vector<GO>& cols, std::vector<double>& vals) {
        for (size_t k = 0; k < cols.size(); ++k)
          if (row == p || cols[k] == p) vals[k] = 0.0;
      });
  MultiVector x(singular->getDomainMap(), 1);
  EXPECT_THROW(
      {
        solver.setMatrix(singular, false);
        solver.solve(*b, x);
        throwIfNumericallySingular(*singular, *b, x);
      },
      SingularMatrixError);
}

// A determinant describes a factorized matrix: asking for it turns reuse off.
TEST(FactorizationReuse, IsOffWhenTheDeterminantIsAsked) {
  MumpsSolver::Options o = withMode(Mode::symmetricIndefinite);
  o.determinant = true;
  MumpsSolver solver(o, world());
  const auto A0 = modelMatrix({}, Layout::contiguous);
  const auto b = test::rightHandSide(*A0, 1);
  test::solved(solver, A0, *b);
  test::solved(solver, modelMatrix(contactSprings(1e4), Layout::contiguous), *b);
  EXPECT_EQ(solver.stats().factorizations, 2);
}

}  // namespace
}  // namespace contactlab
