// The thermal stretch of the finite-strain laws (saint-venant-kirchhoff, neo-hookean,
// simo-miehe): F = F_e F_theta, F_theta = (1 + alpha (T - T_ref)) I (ThermalExpansion.hpp). A
// free expansion F = theta I is stress-free; a held point F = I carries Saint Venant-Kirchhoff's
// exact P = theta (3 lambda + 2 mu) (1 / theta^2 - 1) / 2 I and, for a small heating, every
// law the small-strain -E alpha dT / (1 - 2 nu); the Cauchy stress at theta F_e is the law's at
// F_e; dP/dF at a temperature against central differences; no temperature, bit for bit the
// law without expansion.
#include "tests/unit/materials/MaterialTestSupport.hpp"

#include "core/materials/NeoHookean.hpp"
#include "core/materials/SaintVenantKirchhoff.hpp"
#include "core/materials/SimoMiehe.hpp"

#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <optional>
#include <random>
#include <vector>

namespace contactlab {
namespace {

using tensor3::Mat3;

constexpr double kE = 205000.0, kNu = 0.3, kAlpha = 14e-6, kTref = 20.0, kT = 304.0;

ThermalExpansion alloy690Expansion() {
  ThermalExpansion e;
  e.coefficient = kAlpha;
  e.referenceTemperature = kTref;
  return e;
}

struct Laws {
  std::vector<std::unique_ptr<Material>> all;
  Laws() {
    all.push_back(std::make_unique<SaintVenantKirchhoff>(kE, kNu, 0.0, alloy690Expansion()));
    for (auto volumetric : {NeoHookean::Volumetric::Quadratic, NeoHookean::Volumetric::SimoMiehe})
      all.push_back(
          std::make_unique<NeoHookean>(NeoHookean::fromYoungPoisson(kE, kNu, 0.0, volumetric)
                                           .withThermalExpansion(alloy690Expansion())));
    SimoMiehe::Parameters p;
    p.youngModulus = kE;
    p.poissonRatio = kNu;
    p.yieldStress = 250.0;
    p.isotropicHardening = 2000.0;
    p.expansion = alloy690Expansion();
    all.push_back(std::make_unique<SimoMiehe>(p));
  }
};

struct Result {
  MaterialOutput out;
  std::vector<double> state;
};

Result evaluateAt(const Material& m, const Mat3& F, std::optional<double> temperature) {
  std::vector<double> old(m.stateSize());
  if (!old.empty()) m.initializeState(old.data());
  Result r;
  r.state.resize(m.stateSize());
  MaterialInput in;
  in.F = F;
  in.temperature = temperature;
  in.stateOld = old.empty() ? nullptr : old.data();
  r.out.stateNew = r.state.empty() ? nullptr : r.state.data();
  m.evaluate(in, r.out);
  EXPECT_FALSE(r.out.failed) << m.name() << ": " << r.out.failure;
  return r;
}

Mat3 scaled(double s, Mat3 F) {
  for (double& f : F)
    f *= s;
  return F;
}

Mat3 cauchy(const Mat3& P, const Mat3& F) {
  Mat3 sigma{};
  const double J = tensor3::determinant(F);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int K = 0; K < 3; ++K)
        sigma[i * 3 + j] += P[i * 3 + K] * F[j * 3 + K] / J;
  return sigma;
}

TEST(FiniteStrainThermal, FreeExpansionIsStressFree) {
  const Laws laws;
  const double theta = 1.0 + kAlpha * (kT - kTref);
  for (const auto& law : laws.all) {
    const Result r = evaluateAt(*law, scaled(theta, tensor3::identity()), kT);
    EXPECT_LT(test::maxAbs(r.out.P.data(), 9), 1e-9) << law->name();
    EXPECT_EQ(law->equivalentPlasticStrain(r.state.empty() ? nullptr : r.state.data()), 0.0);
  }
}

TEST(FiniteStrainThermal, HeldPointCarriesTheThermalPressure) {
  const Laws laws;
  // Saint Venant-Kirchhoff exactly: F_e = I / theta, E_e = (1 / theta^2 - 1) / 2 I.
  const double theta = 1.0 + kAlpha * (kT - kTref);
  const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  const double exact = theta * (3 * lambda + 2 * mu) * (1 / (theta * theta) - 1) / 2;  // -2033.7
  const Result svk = evaluateAt(*laws.all[0], tensor3::identity(), kT);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(svk.out.P[i * 4], exact, 1e-12 * std::abs(exact));
  // Every law for a heating of 2 degC: the small-strain value to second order in alpha dT.
  const double T = kTref + 2.0, smallStrain = -kE * kAlpha * 2.0 / (1 - 2 * kNu);
  for (const auto& law : laws.all) {
    const Result r = evaluateAt(*law, tensor3::identity(), T);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(r.out.P[i * 4], smallStrain, 1e-4 * std::abs(smallStrain)) << law->name();
    EXPECT_NEAR(r.out.P[1], 0.0, 1e-12) << law->name();
  }
}

TEST(FiniteStrainThermal, CauchyStressIsTheLawsAtTheElasticPart) {
  const Laws laws;
  std::mt19937 gen(7);
  const double theta = 1.0 + kAlpha * (kT - kTref);
  for (const auto& law : laws.all) {
    const Mat3 Fe = test::randomF(gen, false);
    const Result heated = evaluateAt(*law, scaled(theta, Fe), kT);
    const Result isothermal = evaluateAt(*law, Fe, std::nullopt);
    const Mat3 a = cauchy(heated.out.P, scaled(theta, Fe)), b = cauchy(isothermal.out.P, Fe);
    for (int k = 0; k < 9; ++k)
      EXPECT_NEAR(a[k], b[k], 1e-10 * test::maxAbs(b.data(), 9)) << law->name();
    // The internal variables too, up to the round-off of (theta F_e) / theta.
    for (std::size_t k = 0; k < heated.state.size(); ++k)
      EXPECT_NEAR(heated.state[k], isothermal.state[k], 1e-12) << law->name();
  }
}

TEST(FiniteStrainThermal, TangentAtATemperatureMatchesCentralDifferences) {
  const Laws laws;
  std::mt19937 gen(11);
  for (const auto& law : laws.all)
    for (int sample = 0; sample < 3; ++sample) {
      const Mat3 F = test::randomF(gen, sample == 2);
      const Result r = evaluateAt(*law, F, 250.0);
      const double err = test::centralDifferenceError<9, 9>(
          [&](const Mat3& G) { return evaluateAt(*law, G, 250.0).out.P; }, F, r.out.dPdF.data(),
          1e-6);
      EXPECT_LT(err, 1e-6) << law->name() << " sample " << sample;
    }
}

TEST(FiniteStrainThermal, NoTemperatureIsTheLawWithoutExpansionBitForBit) {
  const Laws laws;
  const SaintVenantKirchhoff plain(kE, kNu);
  std::mt19937 gen(3);
  const Mat3 F = test::randomF(gen, false);
  EXPECT_EQ(evaluateAt(*laws.all[0], F, std::nullopt).out.P, evaluateAt(plain, F, {}).out.P);
  EXPECT_EQ(evaluateAt(*laws.all[0], F, kTref).out.P, evaluateAt(plain, F, {}).out.P);
}

}  // namespace
}  // namespace contactlab
