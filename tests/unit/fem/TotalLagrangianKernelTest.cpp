#include "tests/unit/fem/FemTestSupport.hpp"

#include "core/problem/ElementUpdateError.hpp"
#include "core/problem/SmallStrainKernel.hpp"
#include "core/problem/TotalLagrangianKernel.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>

namespace contactlab {
namespace {

using test::maxAbs;
using test::nameOf;

using test::TestKirchhoff;

using Element = test::KernelElement<TotalLagrangianKernel>;

// A rotation by `angle` about an axis (about z in 2D).
void rotation(int d, double angle, double (&R)[3][3]) {
  const double c = std::cos(angle), s = std::sin(angle);
  const double axis[3] = {d == 2 ? 0.0 : 0.48, d == 2 ? 0.0 : -0.6, d == 2 ? 1.0 : 0.64};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      R[i][j] = c * (i == j) + (1 - c) * axis[i] * axis[j];
  R[0][1] -= s * axis[2], R[1][0] += s * axis[2];
  R[0][2] += s * axis[1], R[2][0] -= s * axis[1];
  R[1][2] -= s * axis[0], R[2][1] += s * axis[0];
}

TEST(TotalLagrangianKernel, FiniteRigidMotionsGiveZeroResidualAndStress) {
  const TestKirchhoff material(60.0, 40.0);
  for (ElementType t : test::solidTypes()) {
    Element e(t);
    double R[3][3];
    rotation(e.d, 1.1, R);  // 63 degrees: far outside the small-strain kernel's reach
    const double c[3] = {0.3, -0.2, 0.1};
    const auto u = e.affineDeformation(R, c);
    std::vector<double> f(e.n * e.d);
    std::array<double, 6> sigma{};
    e.kernel.compute(e.x.data(), u.data(), material, nullptr, nullptr, f.data(), nullptr);
    e.kernel.stresses(e.x.data(), u.data(), material, nullptr, nullptr, nullptr, sigma.data());
    EXPECT_LT(maxAbs(f), 1e-12) << nameOf(t);
    EXPECT_LT(*std::max_element(sigma.begin(), sigma.end(),
                                [](double a, double b) { return std::abs(a) < std::abs(b); }),
              1e-12)
        << nameOf(t);
  }
}

TEST(TotalLagrangianKernel, TangentMatchesFiniteDifferencesAtLargeStrain) {
  const TestKirchhoff material(60.0, 40.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> r(-0.15, 0.15);
  for (ElementType t : test::solidTypes()) {
    Element e(t);
    const int nd = e.n * e.d;
    // A rotated stretch plus a random perturbation: strains of tens of percent.
    double G[3][3];
    rotation(e.d, 0.7, G);
    for (int i = 0; i < e.d; ++i)
      for (int j = 0; j < e.d; ++j)
        G[i][j] *= (j == 0 ? 1.3 : 0.9);
    const double c[3] = {0, 0, 0};
    auto u = e.affineDeformation(G, c);
    for (double& v : u)
      v += 0.2 * r(rng);
    std::vector<double> f(nd), K(nd * nd), fp(nd), fm(nd);
    e.kernel.compute(e.x.data(), u.data(), material, nullptr, nullptr, f.data(), K.data());
    const double h = 1e-6, scale = maxAbs(K);
    for (int k = 0; k < nd; ++k) {
      auto up = u, um = u;
      up[k] += h, um[k] -= h;
      e.kernel.compute(e.x.data(), up.data(), material, nullptr, nullptr, fp.data(), nullptr);
      e.kernel.compute(e.x.data(), um.data(), material, nullptr, nullptr, fm.data(), nullptr);
      for (int i = 0; i < nd; ++i) {
        EXPECT_NEAR(K[i * nd + k], (fp[i] - fm[i]) / (2 * h), 1e-6 * scale)
            << nameOf(t) << " K(" << i << "," << k << ")";
        // A hyperelastic law gives a symmetric tangent, geometric stiffness included.
        EXPECT_NEAR(K[i * nd + k], K[k * nd + i], 1e-12 * scale) << nameOf(t);
      }
    }
  }
}

TEST(TotalLagrangianKernel, ReducesToTheSmallStrainKernelAtTheReferenceConfiguration) {
  const double E = 70.0, nu = 0.33;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const TestKirchhoff finite(lambda, mu);
  const test::IsotropicElastic small(E, nu);
  for (ElementType t : test::solidTypes()) {
    Element e(t);
    const SmallStrainKernel linear(t);
    const int nd = e.n * e.d;
    const std::vector<double> u(nd, 0.0);
    std::vector<double> f(nd), K(nd * nd), fs(nd), Ks(nd * nd);
    e.kernel.compute(e.x.data(), u.data(), finite, nullptr, nullptr, f.data(), K.data());
    linear.compute(e.x.data(), u.data(), small, nullptr, nullptr, fs.data(), Ks.data());
    const double scale = maxAbs(Ks);
    for (int k = 0; k < nd * nd; ++k)
      EXPECT_NEAR(K[k], Ks[k], 1e-12 * scale) << nameOf(t);
    EXPECT_LT(maxAbs(f), 1e-14);
  }
}

TEST(TotalLagrangianKernel, HomogeneousStretchGivesTheCauchyStress) {
  // Uniaxial stretch F = diag(s, 1, 1): E11 = (s^2 - 1) / 2, S11 = (lambda + 2 mu) E11,
  // S22 = S33 = lambda E11, sigma = F S F^T / J: sigma11 = s S11, sigma22 = S22 / s.
  const double lambda = 60.0, mu = 40.0, s = 1.4;
  const TestKirchhoff material(lambda, mu);
  const double E11 = 0.5 * (s * s - 1);
  for (ElementType t : test::solidTypes()) {
    Element e(t);
    const double G[3][3] = {{s, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const double c[3] = {0, 0, 0};
    const auto u = e.affineDeformation(G, c);
    std::vector<double> points(6 * e.kernel.numQuadraturePoints());
    e.kernel.stresses(e.x.data(), u.data(), material, nullptr, nullptr, points.data(), nullptr);
    for (int q = 0; q < e.kernel.numQuadraturePoints(); ++q) {
      EXPECT_NEAR(points[6 * q + 0], s * (lambda + 2 * mu) * E11, 1e-10) << nameOf(t);
      EXPECT_NEAR(points[6 * q + 1], lambda * E11 / s, 1e-10) << nameOf(t);
      EXPECT_NEAR(points[6 * q + 2], lambda * E11 / s, 1e-10) << nameOf(t);  // plane strain
      EXPECT_NEAR(points[6 * q + 3], 0.0, 1e-10) << nameOf(t);
    }
  }
}

TEST(TotalLagrangianKernel, InvertedElementAndWrongMaterialAreNamed) {
  const TestKirchhoff material(60.0, 40.0);
  for (ElementType t : test::solidTypes()) {
    Element e(t);
    const double G[3][3] = {{-0.5, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // x folded through itself
    const double c[3] = {0, 0, 0};
    const auto u = e.affineDeformation(G, c);
    std::vector<double> f(e.n * e.d);
    try {
      e.kernel.compute(e.x.data(), u.data(), material, nullptr, nullptr, f.data(), nullptr);
      ADD_FAILURE() << nameOf(t) << ": no error for det F < 0";
    } catch (const ElementUpdateError& err) {
      EXPECT_EQ(err.code(), "inverted-element");
      EXPECT_NE(std::string(err.what()).find("det F = -0.5"), std::string::npos) << err.what();
    }
    const test::IsotropicElastic small(1.0, 0.3);
    EXPECT_THROW(e.kernel.compute(e.x.data(), u.data(), small, nullptr, nullptr, f.data(), nullptr),
                 std::invalid_argument);
  }
}

}  // namespace
}  // namespace contactlab
