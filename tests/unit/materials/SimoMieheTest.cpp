// simo-miehe: finite-strain J2 plasticity with the exponential-map return.
// Closed forms (uniaxial stress in logarithmic strain with linear and tabulated hardening,
// reversal, perfect plasticity at large isochoric stretch and shear, the small-strain limit
// against j2-small-strain); objectivity; isochoric plastic flow; failures without throwing;
// parameter validation through the registry. The tangent tests are SimoMieheTangentTest.cpp.
#include "tests/unit/materials/SimoMieheTestSupport.hpp"

#include "core/materials/J2SmallStrain.hpp"
#include "core/materials/MaterialRegistry.hpp"
#include "core/materials/SimoMiehe.hpp"
#include "core/materials/Tensor3.hpp"

#include <Teuchos_Array.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <iostream>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace contactlab {
namespace {

using namespace test;
using namespace test::simo_miehe;

// ---------------------------------------------------------------------------------------------
// Closed forms.

TEST(SimoMiehe, LinearHardeningUniaxialStressMatchesTheLogarithmicClosedForm) {
  // Coaxial loading: ln(stretch) = eps_e + eps_p with eps_p = alpha (2, -1, -1) / 2 and the
  // Hencky law, so in uniaxial Kirchhoff stress tau: ln(l1) = tau / E + alpha,
  // ln(l2) = -nu tau / E - alpha / 2, tau = sigma_y0 + H alpha once plastic. Backward Euler is
  // exact on this proportional path, whatever the step.
  const double H = 20.0;
  const SimoMiehe m(linear(H));
  // The stretches of the uniaxial state with Kirchhoff stress tau and plastic strain eps_p11.
  const auto uniaxial = [](double tau, double plastic) {
    return diagonal(std::exp(tau / kE + plastic), std::exp(-kNu * tau / kE - plastic / 2),
                    std::exp(-kNu * tau / kE - plastic / 2));
  };
  const auto check = [&](const Step& r, const Mat3& F, double tau, double alpha,
                         const std::string& where) {
    EXPECT_NEAR(alphaOf(r.state), alpha, 1e-12 * (1 + alpha)) << where;
    const Mat3 t = kirchhoff(r.out, F);
    EXPECT_NEAR(t[0], tau, 1e-12 * kE) << where;
    for (int a = 1; a < 9; ++a)
      EXPECT_NEAR(t[a], 0.0, 1e-12 * kE) << where << " component " << a;
  };
  State state = virgin(m);
  double tau = 0.0, alpha = 0.0;
  for (int k = 1; k <= 40; ++k) {  // total logarithmic strain up to 0.4
    const double e = 0.01 * k;
    alpha = std::max(0.0, (kE * e - kYield) / (kE + H));
    tau = kE * (e - alpha);
    if (alpha > 0) {
      EXPECT_NEAR(tau, kYield + H * alpha, 1e-12 * kE);
    }
    const Mat3 F = uniaxial(tau, alpha);
    EXPECT_NEAR(std::log(F[0]), e, 1e-14);
    const Step r = step(m, F, state);
    check(r, F, tau, alpha, "loading e = " + std::to_string(e));
    state = r.state;
  }
  // Elastic unloading by 1.5 sigma_y: tau drops by as much, alpha stays.
  const double alphaMax = alpha, tauMax = tau;
  {
    const Mat3 F = uniaxial(tauMax - 1.5 * kYield, alphaMax);
    const Step r = step(m, F, state);
    check(r, F, tauMax - 1.5 * kYield, alphaMax, "unloading");
    EXPECT_EQ(r.state, state);
  }
  // Reverse yield at -(sigma_y0 + H alpha_max) (isotropic hardening), then compression: alpha
  // grows while eps_p11 = 2 alpha_max - alpha.
  for (double extra : {0.01, 0.05, 0.2}) {
    const double a = alphaMax + extra, t = -(kYield + H * a), plastic = 2 * alphaMax - a;
    const Mat3 F = uniaxial(t, plastic);
    const Step r = step(m, F, state);
    check(r, F, t, a, "reverse " + std::to_string(extra));
  }
}

// The curve's yield stress by interpolation written out here (not the law's).
double curveStress(const SimoMiehe::Parameters& p, double alpha) {
  const auto& s = p.hardeningStrains;
  const auto& t = p.hardeningStresses;
  std::size_t i = 0;
  while (i + 2 < s.size() && alpha >= s[i + 1])
    ++i;
  return t[i] + (t[i + 1] - t[i]) / (s[i + 1] - s[i]) * (alpha - s[i]);
}

TEST(SimoMiehe, TabulatedHardeningUniaxialStressFollowsTheCurveAndItsLastSlope) {
  for (const auto& parameters : {concaveCurve(), convexCurve()}) {
    const SimoMiehe m(parameters);
    // Beyond the last point the last slope goes on.
    const auto& s = parameters.hardeningStrains;
    const auto& t = parameters.hardeningStresses;
    const std::size_t n = s.size();
    const double lastSlope = (t[n - 1] - t[n - 2]) / (s[n - 1] - s[n - 2]);
    EXPECT_NEAR(m.yieldStress(s[n - 1] + 0.5), t[n - 1] + 0.5 * lastSlope, 1e-14);
    EXPECT_EQ(m.hardeningSlope(s[n - 1] + 0.5), lastSlope);
    EXPECT_EQ(m.yieldStress(0.0), kYield);
    // Steps that cross several knots at once, and end past the last one.
    State state = virgin(m);
    for (double alpha : {0.001, 0.04, 0.07, 0.25, 0.6, 1.0}) {
      const double tau = curveStress(parameters, alpha);
      const Mat3 F = diagonal(std::exp(tau / kE + alpha), std::exp(-kNu * tau / kE - alpha / 2),
                              std::exp(-kNu * tau / kE - alpha / 2));
      const Step r = step(m, F, state);
      EXPECT_NEAR(alphaOf(r.state), alpha, 1e-12) << alpha;
      const Mat3 k = kirchhoff(r.out, F);
      EXPECT_NEAR(k[0], tau, 1e-12 * kE) << alpha;
      EXPECT_NEAR(k[4], 0.0, 1e-12 * kE) << alpha;
      EXPECT_NEAR(k[8], 0.0, 1e-12 * kE) << alpha;
      state = r.state;
    }
  }
}

TEST(SimoMiehe, TwoPointCurveIsTheLinearLaw) {
  const double H = 20.0;
  SimoMiehe::Parameters p = linear(0.0);
  p.hardeningStrains = {0.0, 0.5};
  p.hardeningStresses = {kYield, kYield + 0.5 * H};
  const SimoMiehe curve(p), linearLaw(linear(H));
  std::mt19937 gen(35);
  for (int sample = 0; sample < 10; ++sample) {
    const Mat3 F = randomF(gen, false);
    const Step a = step(curve, F, virgin(curve)), b = step(linearLaw, F, virgin(linearLaw));
    EXPECT_LT(maxDifference(a.out.P, b.out.P), 1e-12 * kE) << sample;
    EXPECT_NEAR(alphaOf(a.state), alphaOf(b.state), 1e-14) << sample;
  }
}

TEST(SimoMiehe, PerfectPlasticityHoldsTheYieldStressAtLargeIsochoricStrain) {
  const SimoMiehe m(linear(0.0));
  // Isochoric stretch in tension to 2.5 and compression to 0.4, and simple shear to 1.
  const std::vector<std::function<Mat3(double)>> paths = {
      [](double t) {
        const double s = 1 + 1.5 * t;
        return diagonal(s, 1 / std::sqrt(s), 1 / std::sqrt(s));
      },
      [](double t) {
        const double s = 1 - 0.6 * t;
        return diagonal(s, 1 / std::sqrt(s), 1 / std::sqrt(s));
      },
      [](double t) { return Mat3{1, t, 0, 0, 1, 0, 0, 0, 1}; }};
  for (std::size_t path = 0; path < paths.size(); ++path) {
    State state = virgin(m);
    for (int k = 1; k <= 30; ++k) {
      const Mat3 F = paths[path](k / 30.0);
      const Step r = step(m, F, state);
      const Mat3 tau = kirchhoff(r.out, F);
      if (k > 1) {  // plastic from the first step on (strain 0.05 >> 2e-3)
        EXPECT_NEAR(vonMises(tau), kYield, 1e-12 * kYield) << "path " << path << " step " << k;
      }
      EXPECT_NEAR(tensor3::trace(tau), 0.0, 1e-12 * kE) << "path " << path << " step " << k;
      EXPECT_NEAR(tensor3::determinant(inversePlastic(r.state)), 1.0, 1e-12);
      state = r.state;
    }
    EXPECT_GT(alphaOf(state), 0.3) << "path " << path;
  }
}

// The largest differences between simo-miehe and j2-small-strain along one strain path.
struct SmallStrainComparison {
  double stress = 0.0, alpha = 0.0;           // max |sigma - sigma_j2|, max |alpha - p|
  double strain = 0.0, sigma = 0.0, p = 0.0;  // max |eps|, max |sigma_j2|, max p
};

// Both laws with E = 200e3, nu = 0.3, H = 5e3 and the yield stress 20 `scale`, along 40 strain
// increments of 2e-5 `scale` (yield strain 1e-4 `scale`) that load, turn and reverse; F = I + eps
// (no rotation). The small-strain law is homogeneous of degree one in (path, yield stress), so
// what differs between two scales is the finite-strain part alone.
SmallStrainComparison compareWithSmallStrain(double scale) {
  SimoMiehe::Parameters smp;
  smp.youngModulus = 200e3;
  smp.poissonRatio = 0.3;
  smp.yieldStress = 20.0 * scale;
  smp.isotropicHardening = 5e3;
  J2SmallStrain::Parameters j2p;
  j2p.youngModulus = smp.youngModulus;
  j2p.poissonRatio = smp.poissonRatio;
  j2p.yieldStress = smp.yieldStress;
  j2p.isotropicHardening = smp.isotropicHardening;
  const J2SmallStrain j2(j2p);
  const SimoMiehe sm(smp);

  std::mt19937 gen(36);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  std::array<double, J2SmallStrain::kStateSize> j2State{};
  State smState = virgin(sm);
  double eps[6] = {}, direction[6];  // tensor components xx yy zz xy yz xz
  for (double& d : direction)
    d = entry(gen);
  const int voigt[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};
  SmallStrainComparison c;
  for (int k = 0; k < 40; ++k) {
    if (k == 25)
      for (double& d : direction)
        d = -d;  // reverse
    double n = 0.0;
    for (int a = 0; a < 6; ++a) {
      direction[a] = 0.8 * direction[a] + 0.2 * entry(gen);
      n += (a < 3 ? 1.0 : 2.0) * direction[a] * direction[a];
    }
    for (int a = 0; a < 6; ++a)
      eps[a] += 2e-5 * scale * direction[a] / std::sqrt(n);
    MaterialInput in;
    for (int a = 0; a < 6; ++a)
      in.strain[a] = (a < 3 ? 1.0 : 2.0) * eps[a];
    in.stateOld = j2State.data();
    MaterialOutput out;
    out.stateNew = j2State.data();
    j2.evaluate(in, out);
    const Mat3 F = {1 + eps[0], eps[3], eps[5], eps[3],    1 + eps[1],
                    eps[4],     eps[5], eps[4], 1 + eps[2]};
    const Step r = step(sm, F, smState);
    smState = r.state;
    const Mat3 sigma = cauchy(r.out.P, F);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double expected = out.stress[voigt[i][j]];
        c.stress = std::max(c.stress, std::abs(sigma[i * 3 + j] - expected));
        c.sigma = std::max(c.sigma, std::abs(expected));
        c.strain = std::max(c.strain, std::abs(eps[voigt[i][j]]));
      }
    const double p = j2State[J2SmallStrain::kEquivalentPlasticStrain];
    c.alpha = std::max(c.alpha, std::abs(alphaOf(smState) - p));
    c.p = std::max(c.p, p);
  }
  std::cout << "small-strain limit at scale " << scale << ": max |sigma - sigma_j2| = " << c.stress
            << " of max |sigma| " << c.sigma << " at max |eps| " << c.strain
            << "; max |alpha - p| = " << c.alpha << " of max p " << c.p << "\n";
  return c;
}

TEST(SimoMiehe, SmallStrainLimitIsJ2SmallStrain) {
  // The laws differ by the logarithmic vs linearized strain and Kirchhoff vs Cauchy stress:
  // second order in the strain, of the order of (lambda + 2 mu) |eps|^2 in the stress. Halving
  // the path and the yield stress divides the stress difference by 4 and the relative one by 2.
  const double lambda = 200e3 * 0.3 / (1.3 * 0.4), mu = 200e3 / 2.6;
  const SmallStrainComparison full = compareWithSmallStrain(1.0),
                              half = compareWithSmallStrain(0.5);
  for (const auto& c : {full, half}) {
    EXPECT_GT(c.p, 0.5 * c.strain);  // mostly plastic: well beyond the yield strain
    EXPECT_LT(c.stress, 2 * (lambda + 2 * mu) * c.strain * c.strain);
    EXPECT_LT(c.stress, 1e-3 * c.sigma);
    EXPECT_LT(c.alpha, 1e-3 * c.p);
  }
  const double ratio = full.stress / half.stress;
  EXPECT_GT(ratio, 3.5);
  EXPECT_LT(ratio, 4.5);
}

TEST(SimoMiehe, RotatingAPlasticallyDeformedStateRotatesTheStress) {
  for (const Law& law : plasticLaws()) {
    const SimoMiehe m(law.parameters);
    std::mt19937 gen(37);
    for (int sample = 0; sample < 6; ++sample) {
      const Mat3 F1 = randomF(gen, false);
      const Step first = step(m, F1, virgin(m));
      const Mat3 Q = rotation({0.3, -1.0, 0.5 + sample}, 0.4 + 0.5 * sample);
      // Pure rotation of the deformed state: no further flow, P(Q F1) = Q P(F1).
      const Step turned = step(m, tensor3::multiply(Q, F1), first.state);
      EXPECT_EQ(alphaOf(turned.state), alphaOf(first.state)) << law.label;
      EXPECT_LT(maxDifference(turned.out.P, tensor3::multiply(Q, first.out.P)), 1e-12 * kE)
          << law.label << " sample " << sample;
      // A plastic step from that state, with and without the rotation: P and dP/dF rotate,
      // the state (material) does not.
      Mat3 F2 = F1;
      for (int a = 0; a < 9; ++a)
        F2[a] += 0.2 * (F1[a] - (a % 4 == 0 ? 1.0 : 0.0));
      const Step a = step(m, F2, first.state);
      const Step b = step(m, tensor3::multiply(Q, F2), first.state);
      EXPECT_GT(alphaOf(a.state), alphaOf(first.state)) << law.label;
      EXPECT_LT(maxDifference(b.out.P, tensor3::multiply(Q, a.out.P)), 1e-12 * kE) << law.label;
      for (int c = 0; c < 7; ++c)
        EXPECT_NEAR(b.state[c], a.state[c], 1e-12) << law.label << " state " << c;
      double worst = 0.0;
      for (int i = 0; i < 3; ++i)
        for (int J = 0; J < 3; ++J)
          for (int k = 0; k < 3; ++k)
            for (int L = 0; L < 3; ++L) {
              double rotated = 0.0;
              for (int p = 0; p < 3; ++p)
                for (int q = 0; q < 3; ++q)
                  rotated += Q[i * 3 + p] * Q[k * 3 + q] * a.out.dPdF[(p * 3 + J) * 9 + q * 3 + L];
              worst = std::max(worst, std::abs(b.out.dPdF[(i * 3 + J) * 9 + k * 3 + L] - rotated));
            }
      EXPECT_LT(worst, 1e-11 * kE) << law.label << " sample " << sample;
    }
  }
}

TEST(SimoMiehe, PlasticFlowIsIsochoricAndThePressureIsKLnJ) {
  const SimoMiehe m(concaveCurve());
  const double K = kE / (3 * (1 - 2 * kNu));
  std::mt19937 gen(38);
  State state = virgin(m);
  for (int k = 0; k < 8; ++k) {  // a chain of random plastic steps
    const Mat3 F = randomF(gen, false);
    const Step r = step(m, F, state);
    EXPECT_NEAR(tensor3::determinant(inversePlastic(r.state)), 1.0, 1e-12) << k;
    EXPECT_NEAR(tensor3::trace(kirchhoff(r.out, F)) / 3, K * std::log(tensor3::determinant(F)),
                1e-12 * kE)
        << k;
    state = r.state;
  }
  EXPECT_GT(alphaOf(state), 0.0);
}

// ---------------------------------------------------------------------------------------------
// Failures and aliasing.

TEST(SimoMiehe, NonPositiveJAndNonFiniteFSetFailedWithoutThrowing) {
  const SimoMiehe m(linear(20.0));
  State old = virgin(m);
  old[6] = 0.1;
  const auto expectFailure = [&](const Mat3& F, const std::string& prefix) {
    MaterialInput in;
    in.F = F;
    in.stateOld = old.data();
    State next;
    next.fill(std::nan(""));
    MaterialOutput out;
    out.stateNew = next.data();
    EXPECT_NO_THROW(m.evaluate(in, out));
    EXPECT_TRUE(out.failed) << prefix;
    EXPECT_EQ(out.failure.rfind(prefix, 0), 0u) << out.failure;
    EXPECT_EQ(out.failure.find('\n'), std::string::npos);
    for (double p : out.P)
      EXPECT_EQ(p, 0.0);
    for (double d : out.dPdF)
      EXPECT_EQ(d, 0.0);
    EXPECT_EQ(next, old);
    return out.failure;
  };
  EXPECT_EQ(expectFailure(diagonal(1, 1, -0.1), "simo-miehe: J = "), "simo-miehe: J = -0.1 <= 0");
  EXPECT_EQ(expectFailure(diagonal(1, 0, 1), "simo-miehe: J = "), "simo-miehe: J = 0 <= 0");
  EXPECT_EQ(expectFailure({0, 1, 0, 1, 0, 0, 0, 0, 1}, "simo-miehe: J = "),
            "simo-miehe: J = -1 <= 0");  // a reflection
  Mat3 nan = tensor3::identity();
  nan[4] = std::nan("");
  expectFailure(nan, "simo-miehe: J = ");
  Mat3 huge = tensor3::identity();
  huge[0] = std::numeric_limits<double>::infinity();
  expectFailure(huge, "simo-miehe: ");
}

TEST(SimoMiehe, StateNewMayAliasStateOld) {
  const SimoMiehe m(concaveCurve());
  std::mt19937 gen(39);
  const Mat3 F = randomF(gen, false);
  const Step separate = step(m, F, virgin(m));
  State inPlace = virgin(m);
  MaterialInput in;
  in.F = F;
  in.stateOld = inPlace.data();
  MaterialOutput out;
  out.stateNew = inPlace.data();
  m.evaluate(in, out);
  EXPECT_EQ(inPlace, separate.state);
  EXPECT_EQ(out.P, separate.out.P);
  EXPECT_EQ(out.dPdF, separate.out.dPdF);
}

// ---------------------------------------------------------------------------------------------
// Registry entry and parameter validation.

using Setter = std::function<void(Teuchos::ParameterList&)>;

std::unique_ptr<Material> build(const Setter& set) {
  registerMaterials();
  const auto& entry = materialRegistry().get("simo-miehe");
  Teuchos::ParameterList p(*entry.validParameters());  // defaults, as the scene reader fills in
  set(p);
  return entry.build(p);
}

// The message of the std::invalid_argument the build throws, or "" when none is.
std::string refusal(const Setter& set) {
  try {
    build(set);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

Setter values(
    double yield, std::vector<double> strains = {}, std::vector<double> stresses = {},
    const Setter& more = [](Teuchos::ParameterList&) {}) {
  return [=](Teuchos::ParameterList& p) {
    p.set("Yield Stress", yield);
    p.set("Hardening Strains", Teuchos::Array<double>(strains));
    p.set("Hardening Stresses", Teuchos::Array<double>(stresses));
    more(p);
  };
}

Setter with(const std::string& key, double value) {
  return [=](Teuchos::ParameterList& p) { p.set(key, value); };
}

TEST(SimoMiehe, RegisteredWithDocumentedParameters) {
  registerMaterials();
  ASSERT_TRUE(materialRegistry().has("simo-miehe"));
  const auto& entry = materialRegistry().get("simo-miehe");
  EXPECT_FALSE(entry.doc.empty());
  const auto valid = entry.validParameters();
  for (auto it = valid->begin(); it != valid->end(); ++it)
    EXPECT_FALSE(valid->entry(it).docString().empty()) << valid->name(it);
  const auto m = build(values(250.0, {0.0, 0.1}, {250.0, 300.0}, [](Teuchos::ParameterList& p) {
    p.set("E", 200e3);
    p.set("density", 7.8e-9);
  }));
  EXPECT_EQ(m->kinematics(), Kinematics::FiniteStrain);
  EXPECT_EQ(m->stateSize(), 7);
  EXPECT_EQ(m->density(), 7.8e-9);
  const auto& law = dynamic_cast<const SimoMiehe&>(*m);
  EXPECT_EQ(law.parameters().youngModulus, 200e3);
  EXPECT_NEAR(law.yieldStress(0.05), 275.0, 1e-12);
  EXPECT_NEAR(law.yieldStress(0.2), 350.0, 1e-12);  // the last slope goes on
  const auto linearLaw = build(values(250.0, {}, {}, with("Isotropic Hardening Modulus", 1e3)));
  EXPECT_NEAR(dynamic_cast<const SimoMiehe&>(*linearLaw).yieldStress(0.1), 350.0, 1e-12);
}

TEST(SimoMiehe, InvalidParametersAreRefusedNamingTheKey) {
  const double nan = std::nan("");
  const std::vector<std::pair<Setter, std::vector<std::string>>> refusals = {
      {values(1.0, {}, {}, with("E", 0.0)), {"E must be > 0", "(got 0)"}},
      {values(1.0, {}, {}, with("E", -2.0)), {"E must be > 0", "(got -2)"}},
      {values(1.0, {}, {}, with("nu", 0.5)), {"nu must lie in (0, 0.5)", "(got 0.5)"}},
      {values(1.0, {}, {}, with("nu", 0.0)), {"nu must lie in (0, 0.5)", "(got 0)"}},
      {values(1.0, {}, {}, with("nu", -0.2)), {"nu must lie in (0, 0.5)", "(got -0.2)"}},
      {values(0.0), {"Yield Stress must be > 0", "(got 0)"}},
      {values(-1.0), {"Yield Stress must be > 0", "(got -1)"}},
      {values(1.0, {}, {}, with("Isotropic Hardening Modulus", -1.0)),
       {"Isotropic Hardening Modulus must be >= 0", "(got -1)"}},
      {values(1.0, {}, {}, with("density", -1.0)), {"density must be >= 0", "(got -1)"}},
      {values(1.0, {0.0, 0.1}, {1.0, 2.0}, with("Isotropic Hardening Modulus", 5.0)),
       {"either Isotropic Hardening Modulus or a hardening curve", "not both", "(got 5)"}},
      {values(1.0, {0.0, 0.1, 0.1}, {1.0, 2.0, 3.0}),
       {"Hardening Strains must increase strictly (entry 3)", "(got 0.1)"}},
      {values(1.0, {0.0, 0.2, 0.1}, {1.0, 2.0, 3.0}),
       {"Hardening Strains must increase strictly (entry 3)", "(got 0.1)"}},
      {values(1.0, {0.0, 0.1, 0.2}, {1.0, 2.0, 1.5}),
       {"Hardening Stresses must not decrease (entry 3)", "(got 1.5)"}},
      {values(1.0, {0.01, 0.1}, {1.0, 2.0}), {"Hardening Strains must start at 0", "(got 0.01)"}},
      {values(1.0, {0.0, 0.1}, {1.5, 2.0}),
       {"Hardening Stresses must start at the Yield Stress 1", "(got 1.5)"}},
      {values(1.0, {0.0, 0.1, 0.2}, {1.0, 2.0}),
       {"Hardening Strains and Hardening Stresses must have the same number", "(got 3 and 2)"}},
      {values(1.0, {0.0, 0.1}, {}), {"same number of entries", "(got 2 and 0)"}},
      {values(1.0, {0.0}, {1.0}), {"at least two points", "(got 1)"}},
      {values(1.0, {0.0, nan}, {1.0, 2.0}), {"Hardening Strains must be finite", "(got nan)"}},
      {values(1.0, {0.0, 0.1}, {1.0, nan}), {"Hardening Stresses must be finite", "(got nan)"}},
  };
  for (const auto& [set, expected] : refusals) {
    const std::string what = refusal(set);
    ASSERT_FALSE(what.empty()) << "no error for " << expected.front();
    EXPECT_EQ(what.rfind("simo-miehe: ", 0), 0u) << what;
    for (const auto& s : expected)
      EXPECT_NE(what.find(s), std::string::npos) << "'" << s << "' not in: " << what;
  }
  // The boundaries that are valid: a flat curve (perfectly plastic), linear modulus 0 with a
  // curve, nu close to its bounds.
  EXPECT_EQ(refusal(values(1.0, {0.0, 0.1}, {1.0, 1.0})), "");
  EXPECT_EQ(refusal(values(1.0, {}, {}, with("nu", 0.499))), "");
  EXPECT_EQ(refusal(values(1.0, {}, {}, with("nu", 0.01))), "");
}

}  // namespace
}  // namespace contactlab
