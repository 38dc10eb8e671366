#include "tests/unit/fem/FemTestSupport.hpp"

#include "core/fem/InvalidElementError.hpp"
#include "core/problem/SmallStrainKernel.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>

namespace contactlab {
namespace {

using test::maxAbs;
using test::nameOf;

using Element = test::KernelElement<SmallStrainKernel>;

TEST(SmallStrainKernel, RigidBodyMotionsGiveZeroResidual) {
  const test::IsotropicElastic material(100.0, 0.3);
  for (ElementType t : test::solidTypes()) {
    Element e(t);
    std::vector<double> f(e.n * e.d);
    const double zero[3][3] = {};
    const double c[3] = {0.3, -0.2, 0.1};
    e.kernel.compute(e.x.data(), e.affineDisplacement(zero, c).data(), material, nullptr, nullptr,
                     f.data(), nullptr);
    EXPECT_LT(maxAbs(f), 1e-12) << nameOf(t) << " translation";
    // Infinitesimal rotation: skew-symmetric displacement gradient.
    const double W[3][3] = {{0, -0.01, 0.02}, {0.01, 0, -0.03}, {-0.02, 0.03, 0}};
    e.kernel.compute(e.x.data(), e.affineDisplacement(W, c).data(), material, nullptr, nullptr,
                     f.data(), nullptr);
    EXPECT_LT(maxAbs(f), 1e-12) << nameOf(t) << " rotation";
  }
}

TEST(SmallStrainKernel, ConstantStrainGivesExactStress) {
  const test::IsotropicElastic material(100.0, 0.25);
  const double G[3][3] = {{0.01, 0.004, -0.002}, {0.003, -0.02, 0.005}, {0.001, 0.006, 0.015}};
  const double c[3] = {0.1, 0.2, 0.3};
  for (ElementType t : test::solidTypes()) {
    Element e(t);
    // Expected stress from the full 6x6 law with the plane-strain zeros in 2D.
    double eps[6] = {G[0][0], G[1][1], 0, G[0][1] + G[1][0], 0, 0};
    if (e.d == 3) {
      eps[2] = G[2][2];
      eps[4] = G[1][2] + G[2][1];
      eps[5] = G[0][2] + G[2][0];
    }
    double expected[6] = {};
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        expected[i] += material.C()[i * 6 + j] * eps[j];
    const auto u = e.affineDisplacement(G, c);
    test::expectUniformStress(e.kernel, e.x, u, material, expected, nameOf(t));
  }
}

TEST(SmallStrainKernel, LinearTangentIsSymmetricAndGivesTheResidual) {
  const test::IsotropicElastic material(70.0, 0.33);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> r(-0.01, 0.01);
  for (ElementType t : test::solidTypes()) {
    Element e(t);
    const int nd = e.n * e.d;
    std::vector<double> u(nd), f(nd), K(nd * nd);
    for (double& v : u)
      v = r(rng);
    e.kernel.compute(e.x.data(), u.data(), material, nullptr, nullptr, f.data(), K.data());
    const double scale = maxAbs(K);
    for (int i = 0; i < nd; ++i) {
      double Ku = 0;
      for (int j = 0; j < nd; ++j) {
        EXPECT_NEAR(K[i * nd + j], K[j * nd + i], 1e-13 * scale) << nameOf(t);
        Ku += K[i * nd + j] * u[j];
      }
      EXPECT_NEAR(Ku, f[i], 1e-12 * scale) << nameOf(t);
    }
    // Positive diagonal; residual without tangent is the same.
    for (int i = 0; i < nd; ++i)
      EXPECT_GT(K[i * nd + i], 0.0);
    std::vector<double> f2(nd);
    e.kernel.compute(e.x.data(), u.data(), material, nullptr, nullptr, f2.data(), nullptr);
    EXPECT_EQ(f, f2);
  }
}

TEST(SmallStrainKernel, TangentMatchesFiniteDifferencesForNonlinearUnsymmetricMaterial) {
  const test::UnsymmetricNonlinear material;
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> r(-0.05, 0.05);
  for (ElementType t : test::solidTypes()) {
    Element e(t);
    const int nd = e.n * e.d, nq = e.kernel.numQuadraturePoints();
    std::vector<double> u(nd), f(nd), K(nd * nd);
    std::vector<double> stateOld(nq), stateNew(nq);
    e.kernel.initializeState(material, stateOld.data());
    for (int q = 0; q < nq; ++q)
      stateOld[q] = 10 + q;
    for (double& v : u)
      v = r(rng);
    e.kernel.compute(e.x.data(), u.data(), material, stateOld.data(), stateNew.data(), f.data(),
                     K.data());
    for (int q = 0; q < nq; ++q)
      EXPECT_EQ(stateNew[q], 11 + q);
    const bool unsymmetric = test::expectTangentMatchesDifferences(
        e.kernel, e.x, u, material, stateOld.data(), stateNew.data(), K, nameOf(t));
    EXPECT_TRUE(unsymmetric) << nameOf(t) << ": the test material should be unsymmetric";
  }
}

TEST(SmallStrainKernel, BodyForceAndVolume) {
  for (ElementType t : test::solidTypes()) {
    Element e(t);
    const double b[3] = {1.0, -2.0, 0.5};
    std::vector<double> f(e.n * e.d);
    e.kernel.bodyForce(e.x.data(), b, f.data());
    const double volume = e.kernel.volume(e.x.data());
    EXPECT_GT(volume, 0.0);
    for (int i = 0; i < e.d; ++i) {
      double sum = 0;
      for (int a = 0; a < e.n; ++a)
        sum += f[a * e.d + i];
      EXPECT_NEAR(sum, b[i] * volume, 1e-12) << nameOf(t);
    }
    // A position-dependent load integrates like the quadrature rule says.
    e.kernel.bodyForce(
        e.x.data(), [](const double* p, double* v) { v[0] = p[0], v[1] = p[1], v[2] = p[2]; },
        f.data());
    std::vector<double> points(3 * e.kernel.numQuadraturePoints());
    e.kernel.quadraturePoints(e.x.data(), points.data());
    double sum = 0;
    for (int a = 0; a < e.n; ++a)
      sum += f[a * e.d];
    EXPECT_GT(sum, 0.0);
    for (int q = 0; q < e.kernel.numQuadraturePoints(); ++q) {
      // Quadrature points lie inside the element's bounding box.
      for (int i = 0; i < e.d; ++i) {
        double lo = 1e300, hi = -1e300;
        for (int a = 0; a < e.n; ++a)
          lo = std::min(lo, e.x[3 * a + i]), hi = std::max(hi, e.x[3 * a + i]);
        EXPECT_GT(points[3 * q + i], lo);
        EXPECT_LT(points[3 * q + i], hi);
      }
    }
  }
  // Unit square and cube: exact volumes.
  const std::vector<double> square = {0, 0, 0, 2, 0, 0, 2, 3, 0, 0, 3, 0};
  EXPECT_NEAR(SmallStrainKernel(ElementType::Quad4).volume(square.data()), 6.0, 1e-14);
}

TEST(SmallStrainKernel, RejectsWrongInputs) {
  EXPECT_THROW(SmallStrainKernel(ElementType::Line3), std::invalid_argument);
  Element e(ElementType::Hex8);
  std::vector<double> u(24, 0.0), f(24);
  const test::UnsymmetricNonlinear stateful;
  EXPECT_THROW(
      e.kernel.compute(e.x.data(), u.data(), stateful, nullptr, nullptr, f.data(), nullptr),
      std::invalid_argument);
  struct Finite : test::IsotropicElastic {
    Finite() : IsotropicElastic(1, 0.3) {}
    Kinematics kinematics() const override { return Kinematics::FiniteStrain; }
  } finite;
  EXPECT_THROW(e.kernel.compute(e.x.data(), u.data(), finite, nullptr, nullptr, f.data(), nullptr),
               std::invalid_argument);
  // Inverted: swap the bottom and top faces.
  auto x = e.x;
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i)
      std::swap(x[3 * a + i], x[3 * (a + 4) + i]);
  const test::IsotropicElastic elastic(1, 0.3);
  EXPECT_THROW(e.kernel.compute(x.data(), u.data(), elastic, nullptr, nullptr, f.data(), nullptr),
               InvalidElementError);
}

}  // namespace
}  // namespace contactlab
