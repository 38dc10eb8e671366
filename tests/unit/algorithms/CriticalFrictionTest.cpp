// The dense pieces of the uniqueness diagnostic: critical mu as a generalized eigenvalue, and
// determinants kept as mantissa and exponent; doc/verification.md V6 on the one-node spring models
// with the augmented-Lagrangian law's own Jacobian.
#include "algorithms/CriticalFriction.hpp"
#include "formulations/AugmentedLagrangian.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace contactlab {
namespace {

std::vector<double> diag(const std::vector<double>& d) {
  const int n = static_cast<int>(d.size());
  std::vector<double> M(static_cast<std::size_t>(n) * n, 0.0);
  for (int k = 0; k < n; ++k)
    M[static_cast<std::size_t>(k) * n + k] = d[k];
  return M;
}

TEST(CriticalFriction, SmallestPositiveRealRootOfTheDeterminant) {
  // det(A + mu B) = (1 - mu)(2 - mu)(3 + mu): roots 1, 2, -3.
  const CriticalFriction c = criticalFriction(3, diag({1, 2, 3}), diag({-1, -1, 1}));
  EXPECT_NEAR(c.mu, 1.0, 1e-14);
  EXPECT_EQ(c.realRoots, 3);
  EXPECT_EQ(c.infinite, 0);
}

TEST(CriticalFriction, ComplexOrInfiniteRootsAreNotCritical) {
  // det([[mu, 1], [-1, mu]]) = mu^2 + 1 > 0: no real root.
  const CriticalFriction complex = criticalFriction(2, {0, -1, 1, 0}, diag({1, 1}));
  EXPECT_TRUE(std::isinf(complex.mu));
  EXPECT_EQ(complex.realRoots, 0);
  // B singular: det(A + mu B) = 2 (1 + mu) has one finite root (-1) and one at infinity.
  const CriticalFriction infinite = criticalFriction(2, diag({1, 2}), diag({1, 0}));
  EXPECT_TRUE(std::isinf(infinite.mu));
  EXPECT_EQ(infinite.realRoots, 1);
  EXPECT_EQ(infinite.infinite, 1);
}

// The rank-k route (eigenvalues of M) and the pencil (I - M) + s M by QZ give the same roots.
TEST(CriticalFriction, UpdateEigenvaluesMatchThePencil) {
  const int k = 6;
  std::vector<double> M(static_cast<std::size_t>(k) * k);
  for (std::size_t e = 0; e < M.size(); ++e)
    M[e] = std::sin(1.7 * static_cast<double>(e) + 0.3);  // deterministic, non-symmetric
  M[0] = 0.0;
  std::vector<double> A(M.size());
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i)
      A[static_cast<std::size_t>(j) * k + i] =
          (i == j ? 1.0 : 0.0) - M[static_cast<std::size_t>(j) * k + i];
  const CriticalFriction pencil = criticalFriction(k, A, M, 1e-8);
  const CriticalFriction update = criticalFactorOfUpdate(k, M, 1e-8);
  ASSERT_TRUE(std::isfinite(pencil.mu));
  EXPECT_NEAR(update.mu, pencil.mu, 1e-10 * pencil.mu);
  EXPECT_EQ(update.realRoots + update.infinite, pencil.realRoots + pencil.infinite);
  // M = diag(2, -1, 0): s = 1/2, 2 and one root at infinity.
  const CriticalFriction d = criticalFactorOfUpdate(3, diag({2, -1, 0}));
  EXPECT_NEAR(d.mu, 0.5, 1e-15);
  EXPECT_EQ(d.realRoots, 2);
  EXPECT_EQ(d.infinite, 1);
}

TEST(DenseDeterminant, SignAndScaleWithoutOverflow) {
  // 300 x 300 identity times 1e-200: det = 1e-60000, far below the smallest double.
  const int n = 300;
  std::vector<double> tiny = diag(std::vector<double>(n, 1e-200));
  const Determinant t = denseDeterminant(n, tiny);
  EXPECT_EQ(t.sign(), 1);
  EXPECT_NEAR(t.log10Abs(), -60000.0, 1e-8);
  std::vector<double> huge = diag(std::vector<double>(n, -1e200));  // (-1e200)^300
  const Determinant h = denseDeterminant(n, huge);
  EXPECT_EQ(h.sign(), 1);
  EXPECT_NEAR(h.log10Abs(), 60000.0, 1e-8);
  huge[0] = 1e200;  // one sign flipped
  EXPECT_EQ(denseDeterminant(n, huge).sign(), -1);
  // A swap of two rows of the identity: -1 (the pivoting's sign is counted).
  EXPECT_EQ(denseDeterminant(2, {0, 1, 1, 0}).sign(), -1);
  EXPECT_NEAR(denseDeterminant(2, {0, 1, 1, 0}).log10Abs(), 0.0, 1e-15);
  EXPECT_EQ(denseDeterminant(2, {1, 2, 2, 4}).sign(), 0);  // singular
}

// One node on a rigid plane (normal y, tangent x), held by springs of stiffness k_i along
// e_i = (cos a_i, sin a_i), sliding (augmented Lagrangian, status frozen at slip). Unknowns
// (u_t, u_n, p, Lambda): the law's variables (v, g, p, Lambda) are the node's displacements
// themselves, so J = springs + the law's Jacobian, reordered. The law is affine in mu for
// mu > 0 on the slip piece: A and B from two values of mu.
std::vector<double> springJacobian(const std::vector<std::pair<double, double>>& springs, double mu,
                                   double slipDirection) {
  const AugmentedLagrangian law(10.0, 10.0);
  LawInput in;
  in.weight = 1.0;
  in.mu = mu;
  in.nt = 1;
  in.p = 1.0;                          // closed: p^ = p - r_n g = 1
  in.Lambda[0] = 1.5 * slipDirection;  // outside the unit ball: slipping
  in.frozenStatus = 2;
  LawOutput out;
  law.evaluate(in, out);
  const int map[4] = {1, 0, 2, 3};  // unknown -> law variable (v, g, p, Lambda order 1, 0, 2, 3)
  std::vector<double> J(16, 0.0);   // column major
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      J[b * 4 + a] = out.J[map[a] * 4 + map[b]];
  for (const auto& [k, angle] : springs) {
    const double e[2] = {std::cos(angle), std::sin(angle)};
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b)
        J[b * 4 + a] += k * e[a] * e[b];
  }
  return J;
}

double springCriticalMu(const std::vector<std::pair<double, double>>& springs) {
  double mu = std::numeric_limits<double>::infinity();
  for (double s : {1.0, -1.0}) {
    const auto J1 = springJacobian(springs, 0.5, s), J2 = springJacobian(springs, 1.5, s);
    const auto Jm = springJacobian(springs, 1.0, s);
    std::vector<double> A(16), B(16);
    for (int k = 0; k < 16; ++k) {
      B[k] = J2[k] - J1[k];  // per unit mu
      A[k] = J1[k] - 0.5 * B[k];
      EXPECT_NEAR(Jm[k], A[k] + B[k], 1e-12) << "not affine in mu";
    }
    mu = std::min(mu, criticalFriction(4, A, B).mu);
  }
  return mu;
}

TEST(CriticalFriction, OneSpringAtAnAngleGivesTheCotangent) {
  const double pi = std::acos(-1.0);
  for (double deg : {30.0, 45.0, 60.0, 75.0}) {
    const double theta = deg * pi / 180;
    EXPECT_NEAR(springCriticalMu({{2.0, theta}}), 1 / std::tan(theta), 1e-12) << deg;
  }
}

TEST(CriticalFriction, TwoSpringsAtPlusMinusTheta) {
  const double theta = 50 * std::acos(-1.0) / 180, k1 = 3.0, k2 = 1.0;
  EXPECT_NEAR(springCriticalMu({{k1, theta}, {k2, -theta}}),
              (k1 + k2) / std::abs(k1 - k2) / std::tan(theta), 1e-12);
  // Equal springs: the normal-tangential coupling cancels, no critical mu.
  EXPECT_TRUE(std::isinf(springCriticalMu({{2.0, theta}, {2.0, -theta}})));
}

}  // namespace
}  // namespace contactlab
