// PlaneStress (core/materials/PlaneStress.hpp): sigma_zz = 0 with the thickness strain solved at
// the point, against the closed plane-stress forms of linear elasticity and Saint
// Venant-Kirchhoff, and its condensed tangent against central differences of the in-plane
// stress for every kind of law (hyperelastic, J2, Simo-Miehe from a plastic state).
#include "tests/unit/materials/MaterialTestSupport.hpp"

#include "core/materials/J2SmallStrain.hpp"
#include "core/materials/LinearElastic.hpp"
#include "core/materials/NeoHookean.hpp"
#include "core/materials/PlaneStress.hpp"
#include "core/materials/SaintVenantKirchhoff.hpp"
#include "core/materials/SimoMiehe.hpp"

#include <gtest/gtest.h>
#include <memory>
#include <random>
#include <stdexcept>
#include <vector>

namespace contactlab {
namespace {

using tensor3::Mat3;
using test::evaluateStrain;
using test::maxAbs;

constexpr double kE = 200.0, kNu = 0.3;

// The in-plane strain (xx, yy, gamma_xy) of a plane model, as the 2D kernel passes it.
std::array<double, 6> planeStrain(double xx, double yy, double xy) {
  return {xx, yy, 0.0, xy, 0.0, 0.0};
}

TEST(PlaneStress, LinearElasticityIsTheClosedPlaneStressLaw) {
  const PlaneStress law(std::make_shared<LinearElastic>(kE, kNu));
  const double exx = 1e-3, eyy = -4e-4, gxy = 6e-4;
  const MaterialOutput out = evaluateStrain(law, planeStrain(exx, eyy, gxy));
  const double c = kE / (1.0 - kNu * kNu);
  EXPECT_NEAR(out.stress[0], c * (exx + kNu * eyy), 1e-12);
  EXPECT_NEAR(out.stress[1], c * (eyy + kNu * exx), 1e-12);
  EXPECT_NEAR(out.stress[3], kE / (2.0 * (1.0 + kNu)) * gxy, 1e-12);
  EXPECT_EQ(out.stress[2], 0.0);
  ASSERT_TRUE(out.outOfPlane);
  EXPECT_NEAR(*out.outOfPlane, -kNu / (1.0 - kNu) * (exx + eyy), 1e-17);
  // The condensed tangent is the plane-stress matrix; the zz row and column are zero.
  EXPECT_NEAR(out.tangent[0 * 6 + 0], c, 1e-10);
  EXPECT_NEAR(out.tangent[0 * 6 + 1], c * kNu, 1e-10);
  EXPECT_NEAR(out.tangent[1 * 6 + 1], c, 1e-10);
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(out.tangent[2 * 6 + k], 0.0);
    EXPECT_EQ(out.tangent[k * 6 + 2], 0.0);
  }
  EXPECT_TRUE(law.linear());
  EXPECT_EQ(law.name(), "linear-elastic in plane stress");
}

TEST(PlaneStress, AFreeThermalExpansionIsStressFreeThroughTheThickness) {
  LinearElastic::Parameters p;
  p.youngModulus = kE;
  p.poissonRatio = kNu;
  p.expansion.coefficient = 1e-5;
  p.expansion.referenceTemperature = 20.0;
  const PlaneStress law(std::make_shared<LinearElastic>(p));
  const double free = 1e-5 * 80.0;
  const MaterialOutput out = evaluateStrain(law, planeStrain(free, free, 0.0), nullptr, 100.0);
  EXPECT_LT(maxAbs(out.stress.data(), 6), 1e-12);
  EXPECT_NEAR(*out.outOfPlane, free, 1e-15);
}

// Saint Venant-Kirchhoff in plane stress is the plane-strain law with lambda replaced by
// lambda* = 2 lambda mu / (lambda + 2 mu) (S_zz = 0 is linear in E_zz), at any deformation.
TEST(PlaneStress, SaintVenantKirchhoffIsThePlaneStrainLawWithTheReducedLambda) {
  const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  const double reduced = 2 * lambda * mu / (lambda + 2 * mu);
  const double nuReduced = reduced / (2 * (reduced + mu)), eReduced = 2 * mu * (1 + nuReduced);
  const PlaneStress law(std::make_shared<SaintVenantKirchhoff>(kE, kNu));
  const SaintVenantKirchhoff closed(eReduced, nuReduced);
  std::mt19937 gen(7);
  for (int trial = 0; trial < 20; ++trial) {
    const Mat3 F = test::randomF(gen, /*planeStrain=*/true);
    const MaterialOutput out = test::evaluateF(law, F);
    const MaterialOutput reference = test::evaluateF(closed, F);
    for (int i : {0, 1})
      for (int J : {0, 1})
        EXPECT_NEAR(out.P[i * 3 + J], reference.P[i * 3 + J], 1e-10 * kE) << trial;
    EXPECT_EQ(out.P[8], 0.0);
    // F_zz^2 = 1 + 2 E_zz with E_zz = -lambda tr(E_2D) / (lambda + 2 mu).
    const Mat3 C = tensor3::transposeMultiply(F, F);
    const double trace = 0.5 * (C[0] + C[4] - 2.0);
    EXPECT_NEAR(*out.outOfPlane, std::sqrt(1.0 - 2.0 * lambda * trace / (lambda + 2 * mu)), 1e-11);
  }
}

// d(in-plane P)/d(in-plane F) of the wrapper against central differences: the condensed
// tangent is the derivative of the plane-stress response, the thickness following.
double inPlaneTangentError(const Material& law, const Mat3& F, const double* stateOld) {
  const MaterialOutput out = test::evaluateF(law, F, stateOld);
  constexpr int kInPlane[4] = {0, 1, 3, 4};
  std::array<double, 16> tangent{};
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      tangent[a * 4 + b] = out.dPdF[kInPlane[a] * 9 + kInPlane[b]];
  std::array<double, 4> x{};
  for (int b = 0; b < 4; ++b)
    x[b] = F[kInPlane[b]];
  return test::centralDifferenceError<4, 4>(
      [&](const std::array<double, 4>& y) {
        Mat3 G = F;
        for (int b = 0; b < 4; ++b)
          G[kInPlane[b]] = y[b];
        const MaterialOutput o = test::evaluateF(law, G, stateOld);
        std::array<double, 4> p{};
        for (int a = 0; a < 4; ++a)
          p[a] = o.P[kInPlane[a]];
        return p;
      },
      x, tangent.data(), 1e-6);
}

TEST(PlaneStress, FiniteStrainTangentsAreTheDerivativesOfThePlaneStressResponse) {
  SimoMiehe::Parameters plastic;
  plastic.youngModulus = kE;
  plastic.poissonRatio = kNu;
  plastic.yieldStress = 0.4;
  plastic.isotropicHardening = 20.0;
  const std::vector<std::shared_ptr<const Material>> laws = {
      std::make_shared<SaintVenantKirchhoff>(kE, kNu),
      std::make_shared<NeoHookean>(kE / (4 * (1 + kNu)), 6 * (1 - 2 * kNu) / kE),
      std::make_shared<SimoMiehe>(plastic)};
  std::mt19937 gen(11);
  for (const auto& inner : laws) {
    const PlaneStress law(inner);
    std::vector<double> state(law.stateSize());
    if (!state.empty()) law.initializeState(state.data());
    for (int trial = 0; trial < 10; ++trial) {
      const Mat3 F = test::randomF(gen, /*planeStrain=*/true);
      EXPECT_LT(inPlaneTangentError(law, F, state.empty() ? nullptr : state.data()), 1e-6)
          << law.name() << " trial " << trial;
      EXPECT_LT(std::abs(test::evaluateF(law, F, state.empty() ? nullptr : state.data()).P[8]),
                1e-12);
    }
  }
}

TEST(PlaneStress, SmallStrainPlasticTangentIsTheDerivativeOfThePlaneStressResponse) {
  J2SmallStrain::Parameters p;
  p.youngModulus = kE;
  p.poissonRatio = kNu;
  p.yieldStress = 0.4;
  p.isotropicHardening = 20.0;
  p.kinematicHardening = 5.0;
  const PlaneStress law(std::make_shared<J2SmallStrain>(p));
  std::vector<double> state(law.stateSize());
  law.initializeState(state.data());
  constexpr int kInPlane[3] = {0, 1, 3};
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> entry(-1e-2, 1e-2);
  for (int trial = 0; trial < 10; ++trial) {
    const std::array<double, 3> x = {entry(gen), entry(gen), entry(gen)};
    const auto stressOf = [&](const std::array<double, 3>& y) {
      const MaterialOutput o = evaluateStrain(law, planeStrain(y[0], y[1], y[2]), state.data());
      return std::array<double, 3>{o.stress[0], o.stress[1], o.stress[3]};
    };
    const MaterialOutput out = evaluateStrain(law, planeStrain(x[0], x[1], x[2]), state.data());
    std::array<double, 9> tangent{};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        tangent[a * 3 + b] = out.tangent[kInPlane[a] * 6 + kInPlane[b]];
    const double error = test::centralDifferenceError<3, 3>(stressOf, x, tangent.data(), 1e-8);
    EXPECT_LT(error, 1e-5) << trial;
    EXPECT_EQ(out.stress[2], 0.0);
  }
}

TEST(PlaneStress, NeedsALaw) {
  EXPECT_THROW(PlaneStress(nullptr), std::invalid_argument);
}

}  // namespace
}  // namespace contactlab
