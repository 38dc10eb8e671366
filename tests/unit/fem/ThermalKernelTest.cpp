// Every small-strain kernel hands the block's temperature to the material, and the thermal
// strain reaches every normal component it carries: a free thermal expansion u = alpha dT x
// (3D; axisymmetric u_r = alpha dT r, u_z = alpha dT z, whose hoop strain u_r / r = alpha dT
// must lose the thermal strain too) leaves no stress and no internal force; in plane strain,
// where eps_zz = 0, the in-plane expansion (1 + nu) alpha dT leaves sigma_zz = -E alpha dT alone.
// The tangent at a temperature is the residual's derivative.
#include "tests/unit/fem/FemTestSupport.hpp"

#include "core/materials/LinearElastic.hpp"
#include "core/problem/AxisymmetricKernel.hpp"
#include "core/problem/SmallStrainKernel.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace contactlab {
namespace {

using test::maxAbs;
using test::nameOf;

constexpr double kE = 205000.0, kNu = 0.3, kAlpha = 14e-6, kTref = 20.0, kT = 304.0;
constexpr double kThermal = kAlpha * (kT - kTref);

LinearElastic heatedSteel() {
  LinearElastic::Parameters p;
  p.youngModulus = kE;
  p.poissonRatio = kNu;
  p.expansion.coefficient = kAlpha;
  p.expansion.referenceTemperature = kTref;
  return LinearElastic(p);
}

// u = scale * x at every node (3 reference coordinates per node in x, d components in u).
std::vector<double> dilation(const std::vector<double>& x, int n, int d, double scale) {
  std::vector<double> u(n * d);
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < d; ++i)
      u[a * d + i] = scale * x[3 * a + i];
  return u;
}

// Stresses at every quadrature point within 1e-9 of `expected`, and no internal force.
void expectThermalState(const ElementKernel& kernel, const std::vector<double>& x,
                        const std::vector<double>& u, const Material& material,
                        const double (&expected)[6], const std::string& label) {
  const double scale = kE * kThermal;  // 815 MPa: the stress a fully held bar would carry
  std::vector<double> stress(6 * kernel.numQuadraturePoints()), f(u.size());
  kernel.stresses(x.data(), u.data(), material, nullptr, nullptr, stress.data(), nullptr, kT);
  for (int q = 0; q < kernel.numQuadraturePoints(); ++q)
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(stress[6 * q + k], expected[k], 1e-12 * scale) << label << " q=" << q << " " << k;
  kernel.compute(x.data(), u.data(), material, nullptr, nullptr, f.data(), nullptr, kT);
  EXPECT_LT(maxAbs(f), 1e-11 * scale) << label;
}

TEST(ThermalKernels, FreeExpansionIsStressFreeIn3D) {
  const LinearElastic material = heatedSteel();
  for (ElementType t : test::solidTypes()) {
    if (info(t).dim != 3) continue;
    const SmallStrainKernel kernel(t);
    const auto x = test::distortedNodes(t);
    const double zero[6] = {};
    expectThermalState(kernel, x, dilation(x, kernel.numNodes(), 3, kThermal), material, zero,
                       nameOf(t));
  }
}

TEST(ThermalKernels, PlaneStrainExpansionLeavesOnlyTheOutOfPlaneStress) {
  const LinearElastic material = heatedSteel();
  for (ElementType t : test::planeTypes()) {
    const SmallStrainKernel kernel(t);
    const auto x = test::distortedNodes(t);
    const double expected[6] = {0.0, 0.0, -kE * kThermal, 0.0, 0.0, 0.0};
    expectThermalState(kernel, x, dilation(x, kernel.numNodes(), 2, (1.0 + kNu) * kThermal),
                       material, expected, nameOf(t));
  }
}

TEST(ThermalKernels, AxisymmetricExpansionIsStressFreeHoopIncluded) {
  const LinearElastic material = heatedSteel();
  for (ElementType t : test::planeTypes()) {
    const AxisymmetricKernel kernel(t);
    const auto x = test::ringNodes(t);
    const double zero[6] = {};
    const auto u = dilation(x, kernel.numNodes(), 2, kThermal);
    expectThermalState(kernel, x, u, material, zero, nameOf(t));
    // Without the temperature the same displacement is a strained ring.
    std::vector<double> f(u.size());
    kernel.compute(x.data(), u.data(), material, nullptr, nullptr, f.data(), nullptr);
    EXPECT_GT(maxAbs(f), 1e-3) << nameOf(t);
  }
}

TEST(ThermalKernels, TangentAtATemperatureIsTheResidualsDerivative) {
  LinearElastic::Parameters p;
  p.youngModulus = TemperatureDependent({20.0, 304.0}, {205000.0, 190000.0}, "E");
  p.expansion.coefficient = kAlpha;
  const LinearElastic material(p);
  for (ElementType t : {ElementType::Quad8, ElementType::Tri6}) {
    const AxisymmetricKernel kernel(t);
    const auto x = test::ringNodes(t);
    const int nd = 2 * kernel.numNodes();
    std::vector<double> u = dilation(x, kernel.numNodes(), 2, 0.5 * kThermal), f(nd), K(nd * nd);
    for (int k = 0; k < nd; ++k)
      u[k] += 1e-4 * ((k * 7) % 5 - 2);
    kernel.compute(x.data(), u.data(), material, nullptr, nullptr, f.data(), K.data(), 200.0);
    const double h = 1e-6, scale = maxAbs(K);
    std::vector<double> fp(nd), fm(nd);
    for (int k = 0; k < nd; ++k) {
      auto up = u, um = u;
      up[k] += h, um[k] -= h;
      kernel.compute(x.data(), up.data(), material, nullptr, nullptr, fp.data(), nullptr, 200.0);
      kernel.compute(x.data(), um.data(), material, nullptr, nullptr, fm.data(), nullptr, 200.0);
      for (int i = 0; i < nd; ++i)
        EXPECT_NEAR(K[i * nd + k], (fp[i] - fm[i]) / (2 * h), 1e-6 * scale) << nameOf(t);
    }
  }
}

}  // namespace
}  // namespace contactlab
