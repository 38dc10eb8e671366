// Temperature in the small-strain laws (linear-elastic, j2-small-strain): tables in T
// (TemperatureDependent: interpolation, held ends, refused tables); the thermal strain alpha
// (T - T_ref) I against the closed forms of a free, a fully restrained and a uniaxially
// restrained point (Timoshenko & Goodier, Theory of Elasticity, 3rd ed., section 150: the
// thermal stress of a fully restrained body is -E alpha dT / (1 - 2 nu)); no temperature and
// the reference temperature give the stress of a law without thermal terms, bit for bit; the
// tangents at a temperature against central differences; a heated bar held at both ends yields
// at the yield stress of its temperature.
#include "tests/unit/materials/MaterialTestSupport.hpp"

#include "core/materials/J2SmallStrain.hpp"
#include "core/materials/LinearElastic.hpp"
#include "core/materials/MaterialRegistry.hpp"
#include "core/materials/SimoMiehe.hpp"
#include "core/materials/TemperatureDependent.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_ParameterList.hpp>

#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace contactlab {
namespace {

using Voigt = std::array<double, 6>;

// The seed's tube: Alloy 690, heated from 20 to 304 degC.
constexpr double kE = 205000.0, kNu = 0.3, kAlpha = 14e-6, kTref = 20.0, kT = 304.0;
constexpr double kDeltaT = kT - kTref;

struct PointResult {
  Voigt stress;
  std::array<double, 36> tangent;
  std::vector<double> state;
};

PointResult evaluateAt(const Material& m, const Voigt& strain, std::optional<double> temperature,
                       const std::vector<double>& stateOld = {}) {
  std::vector<double> old = stateOld;
  if (old.empty() && m.stateSize() > 0) {
    old.resize(m.stateSize());
    m.initializeState(old.data());
  }
  PointResult r;
  r.state.resize(m.stateSize());
  MaterialInput in;
  in.strain = strain;
  in.temperature = temperature;
  in.stateOld = old.empty() ? nullptr : old.data();
  MaterialOutput out;
  out.stateNew = r.state.empty() ? nullptr : r.state.data();
  m.evaluate(in, out);
  EXPECT_FALSE(out.failed) << out.failure;
  r.stress = out.stress;
  r.tangent = out.tangent;
  return r;
}

LinearElastic::Parameters alloy690() {
  LinearElastic::Parameters p;
  p.youngModulus = kE;
  p.poissonRatio = kNu;
  p.expansion.coefficient = kAlpha;
  p.expansion.referenceTemperature = kTref;
  return p;
}

J2SmallStrain::Parameters alloy690Plastic(double yield, double Hiso) {
  J2SmallStrain::Parameters p;
  p.youngModulus = kE;
  p.poissonRatio = kNu;
  p.yieldStress = yield;
  p.isotropicHardening = Hiso;
  p.expansion.coefficient = kAlpha;
  p.expansion.referenceTemperature = kTref;
  return p;
}

Voigt isotropic(double e) {
  return {e, e, e, 0.0, 0.0, 0.0};
}

TEST(TemperatureDependent, InterpolatesLinearlyAndHoldsTheEndValues) {
  const TemperatureDependent E({20.0, 100.0, 304.0}, {205000.0, 200000.0, 190000.0}, "E");
  EXPECT_FALSE(E.isConstant());
  EXPECT_EQ(E.at(20.0), 205000.0);
  EXPECT_EQ(E.at(100.0), 200000.0);
  EXPECT_EQ(E.at(304.0), 190000.0);
  EXPECT_NEAR(E.at(60.0), 202500.0, 1e-9);
  EXPECT_NEAR(E.at(202.0), 195000.0, 1e-9);
  EXPECT_EQ(E.at(-50.0), 205000.0);  // held below the first temperature
  EXPECT_EQ(E.at(600.0), 190000.0);  // and above the last
  const TemperatureDependent constant = 3.5;
  EXPECT_TRUE(constant.isConstant());
  EXPECT_EQ(constant.at(-1e3), 3.5);
  EXPECT_EQ(constant.at(1e3), 3.5);
}

TEST(TemperatureDependent, RefusesTablesThatAreNotFunctionsOfT) {
  auto message = [](std::vector<double> T, std::vector<double> v) {
    try {
      TemperatureDependent(std::move(T), std::move(v), "Temperature Tables/E");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message({20.0}, {1.0}).find("at least 2 points"), std::string::npos);
  EXPECT_NE(message({20.0, 100.0}, {1.0}).find("as many values"), std::string::npos);
  EXPECT_NE(message({100.0, 20.0}, {1.0, 2.0}).find("strictly increasing"), std::string::npos);
  EXPECT_NE(message({20.0, 20.0}, {1.0, 2.0}).find("entry 2"), std::string::npos);
  EXPECT_NE(message({20.0, 100.0}, {1.0, NAN}).find("Temperature Tables/E"), std::string::npos);
}

TEST(ThermalStrain, FreeExpansionGivesZeroStress) {
  const LinearElastic le(alloy690());
  const J2SmallStrain j2(alloy690Plastic(50.0, 0.0));  // a low yield: any stress would yield
  for (const Material* m : {static_cast<const Material*>(&le), static_cast<const Material*>(&j2)}) {
    const PointResult r = evaluateAt(*m, isotropic(kAlpha * kDeltaT), kT);
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(r.stress[k], 0.0, 1e-12 * kE * kAlpha * kDeltaT) << m->name() << " " << k;
    EXPECT_EQ(m->equivalentPlasticStrain(r.state.data()), 0.0) << m->name();
  }
}

TEST(ThermalStrain, FullyRestrainedPointCarriesMinusEAlphaDeltaTOverOneMinusTwoNu) {
  const LinearElastic le(alloy690());
  const PointResult r = evaluateAt(le, Voigt{}, kT);
  const double expected = -kE * kAlpha * kDeltaT / (1.0 - 2.0 * kNu);  // -2037.7 MPa
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(r.stress[k], expected, 1e-12 * std::abs(expected)) << k;
  for (int k = 3; k < 6; ++k)
    EXPECT_EQ(r.stress[k], 0.0) << k;
  // Cooling below T_ref pulls: the sign follows T - T_ref.
  EXPECT_NEAR(evaluateAt(le, Voigt{}, kTref - 100.0).stress[0],
              kE * kAlpha * 100.0 / (1.0 - 2.0 * kNu), 1e-9);
}

TEST(ThermalStrain, UniaxiallyRestrainedBarCarriesMinusEAlphaDeltaT) {
  // Held along z, free laterally: eps_xx = eps_yy = (1 + nu) alpha dT makes sigma_xx = 0.
  const LinearElastic le(alloy690());
  const double lateral = (1.0 + kNu) * kAlpha * kDeltaT;
  const PointResult r = evaluateAt(le, Voigt{lateral, lateral, 0.0, 0.0, 0.0, 0.0}, kT);
  EXPECT_NEAR(r.stress[0], 0.0, 1e-12 * kE * kAlpha * kDeltaT);
  EXPECT_NEAR(r.stress[1], 0.0, 1e-12 * kE * kAlpha * kDeltaT);
  EXPECT_NEAR(r.stress[2], -kE * kAlpha * kDeltaT, 1e-12 * kE * kAlpha * kDeltaT);  // -815.1
}

TEST(ThermalStrain, NoTemperatureOrTheReferenceGivesTheMechanicalStressBitForBit) {
  const LinearElastic plain(kE, kNu), thermal(alloy690());
  J2SmallStrain::Parameters withoutExpansion = alloy690Plastic(250.0, 1000.0);
  withoutExpansion.expansion = ThermalExpansion{};
  const J2SmallStrain j2Plain(withoutExpansion);
  const J2SmallStrain j2Thermal(alloy690Plastic(250.0, 1000.0));
  const Voigt strain{2e-3, -1e-3, 4e-4, 1.5e-3, -3e-4, 7e-4};  // plastic for the J2 law
  for (const std::optional<double>& T : {std::optional<double>(), std::optional<double>(kTref)}) {
    EXPECT_EQ(evaluateAt(thermal, strain, T).stress, evaluateAt(plain, strain, {}).stress);
    const PointResult a = evaluateAt(j2Thermal, strain, T), b = evaluateAt(j2Plain, strain, {});
    EXPECT_EQ(a.stress, b.stress);
    EXPECT_EQ(a.state, b.state);
    EXPECT_GT(j2Thermal.equivalentPlasticStrain(a.state.data()), 0.0);
  }
}

TEST(ThermalStrain, TabulatedModulusAndSecantAlphaAreReadAtTheTemperature) {
  LinearElastic::Parameters p = alloy690();
  p.youngModulus = TemperatureDependent({20.0, 304.0}, {205000.0, 190000.0}, "E");
  p.expansion.coefficient = TemperatureDependent({20.0, 304.0}, {13e-6, 14e-6}, "alpha");
  const LinearElastic le(p);
  for (double T : {162.0, 304.0, 400.0}) {
    const double E = p.youngModulus.at(T), alpha = p.expansion.coefficient.at(T);
    const double expected = -E * alpha * (T - kTref) / (1.0 - 2.0 * kNu);
    EXPECT_NEAR(evaluateAt(le, Voigt{}, T).stress[0], expected, 1e-12 * std::abs(expected)) << T;
  }
  // At T = 162 the table gives E = 197500 and alpha = 13.5e-6.
  EXPECT_NEAR(evaluateAt(le, Voigt{}, 162.0).stress[1],
              -197500.0 * 13.5e-6 * 142.0 / (1.0 - 2.0 * kNu), 1e-9);
}

TEST(ThermalStrain, TangentsAtATemperatureMatchCentralDifferences) {
  LinearElastic::Parameters lp = alloy690();
  lp.poissonRatio = TemperatureDependent({20.0, 304.0}, {0.3, 0.31}, "nu");
  const LinearElastic le(lp);
  J2SmallStrain::Parameters jp = alloy690Plastic(250.0, 1000.0);
  jp.yieldStress = TemperatureDependent({20.0, 304.0}, {300.0, 220.0}, "Yield Stress");
  jp.kinematicHardening = TemperatureDependent({20.0, 304.0}, {500.0, 800.0}, "H_kin");
  const J2SmallStrain j2(jp);
  // Plastic at 250 degC from the free-expansion strain plus a deviatoric part.
  const double thermal = kAlpha * (250.0 - kTref);
  const Voigt strain{thermal + 2e-3, thermal - 1.2e-3, thermal + 3e-4, 1e-3, -4e-4, 6e-4};
  for (const Material* m : {static_cast<const Material*>(&le), static_cast<const Material*>(&j2)}) {
    const PointResult r = evaluateAt(*m, strain, 250.0);
    const double err = test::centralDifferenceError<6, 6>(
        [&](const Voigt& e) { return evaluateAt(*m, e, 250.0).stress; }, strain, r.tangent.data(),
        1e-8);
    EXPECT_LT(err, 1e-6) << m->name();
  }
  EXPECT_GT(j2.equivalentPlasticStrain(evaluateAt(j2, strain, 250.0).state.data()), 0.0);
}

// A bar held at both ends along z, free laterally, heated in steps from T_ref: the lateral
// strains that free sigma_xx = sigma_yy by Newton on the law's own tangent. Returns sigma_zz.
double heatedRestrainedBar(const J2SmallStrain& law, const std::vector<double>& temperatures,
                           std::vector<double>& state) {
  double lateral = 0.0, sigmaZZ = 0.0;
  for (double T : temperatures) {
    for (int it = 0; it < 50; ++it) {
      const PointResult r = evaluateAt(law, Voigt{lateral, lateral, 0.0, 0.0, 0.0, 0.0}, T, state);
      sigmaZZ = r.stress[2];
      if (std::abs(r.stress[0]) < 1e-11 * kE) {
        state = r.state;
        break;
      }
      lateral -= r.stress[0] / (r.tangent[0] + r.tangent[1]);
    }
  }
  return sigmaZZ;
}

TEST(ThermalStrain, HeatedRestrainedBarYieldsAtTheYieldStressOfItsTemperature) {
  // Bilinear uniaxial response to the mechanical strain -alpha dT: |sigma| = sigma_y(T) +
  // E H / (E + H) (alpha dT - sigma_y(T) / E), with sigma_y falling from 300 to 220 MPa as it
  // heats (monotonic loading: the path does not matter).
  J2SmallStrain::Parameters p = alloy690Plastic(300.0, 2000.0);
  p.yieldStress = TemperatureDependent({20.0, 304.0}, {300.0, 220.0}, "Yield Stress");
  const J2SmallStrain law(p);
  std::vector<double> state(law.stateSize());
  law.initializeState(state.data());
  std::vector<double> temperatures;
  for (int k = 1; k <= 8; ++k)
    temperatures.push_back(kTref + kDeltaT * k / 8.0);
  const double sigma = heatedRestrainedBar(law, temperatures, state);
  const double H = 2000.0, yieldAtT = 220.0;
  const double expected = -(yieldAtT + kE * H / (kE + H) * (kAlpha * kDeltaT - yieldAtT / kE));
  EXPECT_NEAR(sigma, expected, 1e-9 * std::abs(expected));  // -225.7 MPa, not -815 elastic
  EXPECT_NEAR(law.equivalentPlasticStrain(state.data()),
              (kE * kAlpha * kDeltaT - yieldAtT) / (kE + H), 1e-12);
}

Teuchos::Array<double> column(const std::vector<double>& values) {
  return Teuchos::Array<double>(values);
}

Teuchos::ParameterList registryParameters(const std::string& law) {
  registerMaterials();
  return Teuchos::ParameterList(*materialRegistry().get(law).validParameters());
}

std::string buildError(const std::string& law, const Teuchos::ParameterList& p) {
  try {
    materialRegistry().get(law).build(p);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ThermalStrain, RegistryReadsTablesAndRefusesTwoValuesForOneParameter) {
  Teuchos::ParameterList p = registryParameters("linear-elastic");
  p.set("Thermal Expansion", kAlpha);
  p.set("Reference Temperature", kTref);
  auto& tables = p.sublist("Temperature Tables");
  tables.set("Temperatures", column({20.0, 304.0}));
  tables.set("E", column({205000.0, 190000.0}));
  const auto law = materialRegistry().get("linear-elastic").build(p);
  const auto& le = dynamic_cast<const LinearElastic&>(*law);
  EXPECT_EQ(le.referenceTemperature(), std::optional<double>(kTref));
  EXPECT_NEAR(le.parameters().youngModulus.at(162.0), 197500.0, 1e-9);
  EXPECT_EQ(le.parameters().expansion.coefficient.at(162.0), kAlpha);

  Teuchos::ParameterList both = p;
  both.set("E", 205000.0);
  EXPECT_NE(buildError("linear-elastic", both).find("give E or Temperature Tables/E, not both"),
            std::string::npos);
  Teuchos::ParameterList noColumn = registryParameters("j2-small-strain");
  noColumn.set("Yield Stress", 250.0);
  noColumn.sublist("Temperature Tables").set("Temperatures", column({20.0, 304.0}));
  EXPECT_NE(buildError("j2-small-strain", noColumn).find("no parameter column"), std::string::npos);
  Teuchos::ParameterList negative = registryParameters("j2-small-strain");
  negative.sublist("Temperature Tables").set("Temperatures", column({20.0, 304.0}));
  negative.sublist("Temperature Tables").set("Yield Stress", column({250.0, -1.0}));
  EXPECT_NE(buildError("j2-small-strain", negative).find("Yield Stress must be > 0 (got -1)"),
            std::string::npos);
  // The finite-strain laws read alpha and T_ref too (FiniteStrainThermalTest.cpp tests them).
  Teuchos::ParameterList finite = registryParameters("simo-miehe");
  finite.set("Yield Stress", 250.0);
  finite.set("Reference Temperature", 10.0);
  finite.sublist("Temperature Tables").set("Temperatures", column({20.0, 304.0}));
  finite.sublist("Temperature Tables").set("Thermal Expansion", column({13e-6, 14e-6}));
  const auto simoMiehe = materialRegistry().get("simo-miehe").build(finite);
  EXPECT_EQ(simoMiehe->referenceTemperature(), std::optional<double>(10.0));
  EXPECT_NEAR(dynamic_cast<const SimoMiehe&>(*simoMiehe).parameters().expansion.strain(162.0),
              13.5e-6 * 152.0, 1e-15);
}

}  // namespace
}  // namespace contactlab
