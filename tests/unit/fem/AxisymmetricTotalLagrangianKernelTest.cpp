// The finite-strain axisymmetric kernel (core/problem/AxisymmetricTotalLagrangianKernel.hpp):
// at the reference configuration it is the small-strain axisymmetric kernel; a homogeneous
// stretch u_r = a R, u_z = b Z gives F = diag(1 + a, 1 + b, 1 + a) and the Cauchy stress of
// that F at every point; the tangent is the residual's derivative at large strain; the axial
// translation is free (a finite one too), the radial one is not.
#include "tests/unit/fem/FemTestSupport.hpp"

#include "core/problem/AxisymmetricKernel.hpp"
#include "core/problem/AxisymmetricTotalLagrangianKernel.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

namespace contactlab {
namespace {

using test::maxAbs;
using test::nameOf;

using test::planeTypes;
using test::ringNodes;

constexpr double kE = 70.0, kNu = 0.33;
constexpr double kLambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), kMu = kE / (2 * (1 + kNu));

TEST(AxisymmetricTotalLagrangianKernel, ReducesToTheSmallStrainKernelAtTheReference) {
  const test::TestKirchhoff finite(kLambda, kMu);
  const test::IsotropicElastic small(kE, kNu);
  for (ElementType t : planeTypes()) {
    const AxisymmetricTotalLagrangianKernel kernel(t);
    const AxisymmetricKernel linear(t);
    const auto x = ringNodes(t);
    const int nd = kernel.numDofs();
    const std::vector<double> u(nd, 0.0);
    std::vector<double> f(nd), K(nd * nd), fs(nd), Ks(nd * nd);
    kernel.compute(x.data(), u.data(), finite, nullptr, nullptr, f.data(), K.data());
    linear.compute(x.data(), u.data(), small, nullptr, nullptr, fs.data(), Ks.data());
    const double scale = maxAbs(Ks);
    for (int k = 0; k < nd * nd; ++k)
      EXPECT_NEAR(K[k], Ks[k], 1e-12 * scale) << nameOf(t);
    EXPECT_LT(maxAbs(f), 1e-14);
  }
}

TEST(AxisymmetricTotalLagrangianKernel, HomogeneousStretchGivesTheCauchyStress) {
  // F = diag(s, v, s): E = diag(s^2 - 1, v^2 - 1, s^2 - 1) / 2, S = lambda tr E I + 2 mu E,
  // sigma = F S F^T / det F.
  const test::TestKirchhoff material(kLambda, kMu);
  const double s = 1.3, v = 0.8;
  const double Err = 0.5 * (s * s - 1), Ezz = 0.5 * (v * v - 1), tr = 2 * Err + Ezz;
  const double J = s * v * s;
  const double expected[4] = {s * s * (kLambda * tr + 2 * kMu * Err) / J,
                              v * v * (kLambda * tr + 2 * kMu * Ezz) / J,
                              s * s * (kLambda * tr + 2 * kMu * Err) / J, 0.0};
  for (ElementType t : planeTypes()) {
    const AxisymmetricTotalLagrangianKernel kernel(t);
    const auto x = ringNodes(t);
    std::vector<double> u(kernel.numDofs());
    for (int a = 0; a < kernel.numNodes(); ++a)
      u[2 * a] = (s - 1) * x[3 * a], u[2 * a + 1] = (v - 1) * x[3 * a + 1];
    std::vector<double> points(6 * kernel.numQuadraturePoints());
    kernel.stresses(x.data(), u.data(), material, nullptr, nullptr, points.data(), nullptr);
    for (int q = 0; q < kernel.numQuadraturePoints(); ++q)
      for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(points[6 * q + k], expected[k], 1e-10) << nameOf(t) << " q=" << q;
  }
}

TEST(AxisymmetricTotalLagrangianKernel, TangentIsTheResidualsDerivativeAtLargeStrain) {
  const test::TestKirchhoff material(kLambda, kMu);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> r(-0.15, 0.15);
  for (ElementType t : planeTypes()) {
    const AxisymmetricTotalLagrangianKernel kernel(t);
    const auto x = ringNodes(t);
    const int nd = kernel.numDofs();
    std::vector<double> u(nd), f(nd), K(nd * nd);
    for (double& v : u)
      v = r(rng);
    kernel.compute(x.data(), u.data(), material, nullptr, nullptr, f.data(), K.data());
    test::expectTangentMatchesDifferences(kernel, x, u, material, nullptr, nullptr, K, nameOf(t));
  }
}

TEST(AxisymmetricTotalLagrangianKernel, AxialTranslationIsFreeRadialIsNot) {
  const test::TestKirchhoff material(kLambda, kMu);
  for (ElementType t : planeTypes()) {
    const AxisymmetricTotalLagrangianKernel kernel(t);
    const auto x = ringNodes(t);
    std::vector<double> u(kernel.numDofs(), 0.0), f(kernel.numDofs());
    for (int a = 0; a < kernel.numNodes(); ++a)
      u[2 * a + 1] = 0.7;  // a finite axial translation
    kernel.compute(x.data(), u.data(), material, nullptr, nullptr, f.data(), nullptr);
    EXPECT_LT(maxAbs(f), 1e-12) << nameOf(t);
    for (int a = 0; a < kernel.numNodes(); ++a)
      u[2 * a] = 0.1, u[2 * a + 1] = 0.0;
    kernel.compute(x.data(), u.data(), material, nullptr, nullptr, f.data(), nullptr);
    EXPECT_GT(maxAbs(f), 1e-3) << nameOf(t) << ": a radial translation stretches the hoops";
  }
}

}  // namespace
}  // namespace contactlab
