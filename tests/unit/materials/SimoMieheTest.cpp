// simo-miehe: finite-strain J2 plasticity with the exponential-map return.
// The consistent dP/dF against central differences (elastic, plastic from the virgin and from a
// pre-strained state, elastic unloading, linear / perfect / tabulated hardening, equal and
// near-equal principal stretches); closed forms (uniaxial stress in logarithmic strain with
// linear and tabulated hardening, reversal, perfect plasticity at large isochoric stretch and
// shear, the small-strain limit against j2-small-strain); objectivity; isochoric plastic flow;
// failures without throwing; parameter validation through the registry.
#include "tests/unit/materials/MaterialTestSupport.hpp"

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
using tensor3::Mat3;
using State = std::array<double, SimoMiehe::kStateSize>;

// Yield strain 2e-3: every random F of the tangent tests (|F - I| >= 0.05) yields.
constexpr double kE = 200.0, kNu = 0.3, kYield = 0.4;
// Relative tolerance of the central-difference checks (h = 1e-6 on F ~ 1).
constexpr double kTangentTolerance = 1e-7;

SimoMiehe::Parameters linear(double H, double yield = kYield) {
  SimoMiehe::Parameters p;
  p.youngModulus = kE;
  p.poissonRatio = kNu;
  p.yieldStress = yield;
  p.isotropicHardening = H;
  return p;
}

// Hardening that saturates (slopes 10, 1.25, 0.1, then 0.1 on) and one that stiffens (1, 3).
SimoMiehe::Parameters concaveCurve() {
  SimoMiehe::Parameters p = linear(0.0);
  p.hardeningStrains = {0.0, 0.02, 0.1, 0.3};
  p.hardeningStresses = {kYield, 0.6, 0.7, 0.72};
  return p;
}

SimoMiehe::Parameters convexCurve() {
  SimoMiehe::Parameters p = linear(0.0);
  p.hardeningStrains = {0.0, 0.05, 0.1};
  p.hardeningStresses = {kYield, 0.45, 0.6};
  return p;
}

struct Law {
  std::string label;
  SimoMiehe::Parameters parameters;
};

std::vector<Law> plasticLaws() {
  return {{"linear H = 20", linear(20.0)},
          {"perfectly plastic", linear(0.0)},
          {"tabulated concave", concaveCurve()},
          {"tabulated convex", convexCurve()}};
}

State virgin(const SimoMiehe& m) {
  State s;
  s.fill(7.0);
  m.initializeState(s.data());
  return s;
}

double alphaOf(const State& s) {
  return s[SimoMiehe::kEquivalentPlasticStrain];
}

struct Step {
  MaterialOutput out;
  State state;
};

Step step(const SimoMiehe& m, const Mat3& F, const State& stateOld) {
  Step r;
  r.state.fill(std::nan(""));  // the law must write every entry
  MaterialInput in;
  in.F = F;
  in.stateOld = stateOld.data();
  r.out.stateNew = r.state.data();
  m.evaluate(in, r.out);
  EXPECT_FALSE(r.out.failed) << r.out.failure;
  for (double s : r.state)
    EXPECT_TRUE(std::isfinite(s));
  return r;
}

Mat3 inversePlastic(const State& s) {
  const double* c = s.data() + SimoMiehe::kInversePlasticStrain;
  return {c[0], c[3], c[5], c[3], c[1], c[4], c[5], c[4], c[2]};
}

// Kirchhoff stress tau = P F^T and its von Mises value sqrt(3/2) |dev tau|.
Mat3 kirchhoff(const MaterialOutput& out, const Mat3& F) {
  return tensor3::multiplyTranspose(out.P, F);
}

double vonMises(const Mat3& tau) {
  const double p = tensor3::trace(tau) / 3.0;
  double s2 = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double d = tau[i * 3 + j] - (i == j ? p : 0.0);
      s2 += d * d;
    }
  return std::sqrt(1.5 * s2);
}

double maxDifference(const Mat3& a, const Mat3& b) {
  double m = 0.0;
  for (int i = 0; i < 9; ++i)
    m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

// The largest relative central-difference error of the current tangent test, printed (and
// reset) at its end: the figures the commit reports.
double worstTangentError = 0.0;

void expectTangent(const SimoMiehe& m, const Mat3& F, const State& stateOld,
                   const std::string& label) {
  const double err = dPdFError(m, F, stateOld.data());
  worstTangentError = std::max(worstTangentError, err);
  EXPECT_LT(err, kTangentTolerance) << label;
}

void reportTangentError(const std::string& test) {
  std::cout << test << ": largest relative central-difference error of dP/dF " << worstTangentError
            << "\n";
  worstTangentError = 0.0;
}

// True when alpha lies within `margin` of a knot of the curve (a kink of the yield stress, where
// central differences straddle two slopes).
bool nearKnot(const SimoMiehe::Parameters& p, double alpha, double margin = 1e-4) {
  for (double s : p.hardeningStrains)
    if (std::abs(alpha - s) < margin) return true;
  return false;
}

// ---------------------------------------------------------------------------------------------
// The symmetric eigensolver the law rests on.

TEST(Tensor3, SymmetricEigenReconstructsWithOrthonormalVectorsAlsoForRepeatedValues) {
  std::mt19937 gen(30);
  std::vector<Mat3> cases = {tensor3::identity(), Mat3{}, diagonal(2, 2, 5), diagonal(3, 1, 3)};
  const Mat3 Q0 = rotation({1, 2, 3}, 0.9);
  for (const Mat3& D : {diagonal(2, 2, 5), diagonal(1, 1 + 1e-12, 4), diagonal(7, 7, 7)})
    cases.push_back(tensor3::multiply(Q0, tensor3::multiplyTranspose(D, Q0)));
  for (int k = 0; k < 20; ++k) {
    const Mat3 F = randomF(gen, k % 2 == 1);
    cases.push_back(tensor3::multiplyTranspose(F, F));
  }
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const Mat3& A = cases[c];
    std::array<double, 3> values;
    Mat3 Q;
    ASSERT_TRUE(tensor3::symmetricEigen(A, values, Q)) << c;
    const double scale = std::max(1.0, maxAbs(A.data(), 9));
    Mat3 rebuilt{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int a = 0; a < 3; ++a)
          rebuilt[i * 3 + j] += values[a] * Q[i * 3 + a] * Q[j * 3 + a];
    EXPECT_LT(maxDifference(rebuilt, A), 1e-14 * scale) << c;
    EXPECT_LT(maxDifference(tensor3::transposeMultiply(Q, Q), tensor3::identity()), 1e-14) << c;
  }
  std::array<double, 3> values;
  Mat3 Q;
  Mat3 bad = tensor3::identity();
  bad[1] = std::nan("");
  EXPECT_FALSE(tensor3::symmetricEigen(bad, values, Q));
}

// ---------------------------------------------------------------------------------------------
// State layout, the reference configuration.

TEST(SimoMiehe, StateLayoutAndInitialState) {
  const SimoMiehe m(linear(20.0));
  EXPECT_EQ(m.name(), "simo-miehe");
  EXPECT_EQ(m.kinematics(), Kinematics::FiniteStrain);
  EXPECT_EQ(m.stateSize(), 7);
  const State s = virgin(m);
  EXPECT_EQ(s, (State{1, 1, 1, 0, 0, 0, 0}));
  State t = s;
  t[6] = 0.25;
  EXPECT_EQ(m.equivalentPlasticStrain(t.data()), 0.25);
}

TEST(SimoMiehe, IdentityGivesZeroStressAndTheLinearElasticTangent) {
  const SimoMiehe m(linear(20.0));
  const Step r = step(m, tensor3::identity(), virgin(m));
  EXPECT_LT(maxAbs(r.out.P.data(), 9), 1e-15 * kE);
  const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J)
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L) {
          const double c =
              lambda * (i == J) * (k == L) + mu * ((i == k) * (J == L) + (i == L) * (J == k));
          EXPECT_NEAR(r.out.dPdF[(i * 3 + J) * 9 + k * 3 + L], c, 1e-12 * kE) << i << J << k << L;
        }
}

// ---------------------------------------------------------------------------------------------
// The consistent tangent against central differences.

TEST(SimoMiehe, TangentMatchesCentralDifferencesInElasticStates) {
  // A yield stress no sample reaches: the Hencky law at |F - I| up to 0.5.
  const SimoMiehe m(linear(20.0, 1e3 * kE));
  std::mt19937 gen(31);
  for (int sample = 0; sample < 30; ++sample) {
    const Mat3 F = randomF(gen, sample >= 20);
    ASSERT_EQ(alphaOf(step(m, F, virgin(m)).state), 0.0);
    expectTangent(m, F, virgin(m), "elastic sample " + std::to_string(sample));
  }
  reportTangentError("elastic");
}

TEST(SimoMiehe, TangentMatchesCentralDifferencesInPlasticLoadingFromTheVirginState) {
  for (const Law& law : plasticLaws()) {
    const SimoMiehe m(law.parameters);
    std::mt19937 gen(32);
    int tested = 0;
    for (int sample = 0; sample < 16; ++sample) {
      const Mat3 F = randomF(gen, sample % 4 == 3);
      const double alpha = alphaOf(step(m, F, virgin(m)).state);
      ASSERT_GT(alpha, 0.0) << law.label << " sample " << sample << ": not plastic";
      if (nearKnot(law.parameters, alpha)) continue;
      expectTangent(m, F, virgin(m), law.label + " sample " + std::to_string(sample));
      ++tested;
    }
    EXPECT_GE(tested, 12) << law.label;
  }
  reportTangentError("plastic from the virgin state");
}

// The consistent dP/dF has the major symmetry dP_iJ/dF_kL = dP_kL/dF_iJ (the return is a
// closest-point projection in the logarithmic stresses): the assembled tangent is symmetric, so
// the linear solver may take it as such (Linear Solver/mumps/Mode: automatic).
TEST(SimoMiehe, TangentHasTheMajorSymmetryInPlasticLoading) {
  for (const Law& law : plasticLaws()) {
    const SimoMiehe m(law.parameters);
    std::mt19937 gen(33);
    for (int sample = 0; sample < 16; ++sample) {
      const Mat3 F = randomF(gen, sample % 4 == 3);
      const Step r = step(m, F, virgin(m));
      ASSERT_GT(alphaOf(r.state), 0.0);
      const double scale = maxAbs(r.out.dPdF.data(), 81);
      double asymmetry = 0.0;
      for (int a = 0; a < 9; ++a)
        for (int b = 0; b < 9; ++b)
          asymmetry = std::max(asymmetry, std::abs(r.out.dPdF[a * 9 + b] - r.out.dPdF[b * 9 + a]));
      EXPECT_LT(asymmetry, 1e-10 * scale) << law.label << " sample " << sample;
    }
  }
}

TEST(SimoMiehe, TangentMatchesCentralDifferencesInPlasticLoadingFromAPrestrainedState) {
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  for (const Law& law : plasticLaws()) {
    const SimoMiehe m(law.parameters);
    std::mt19937 gen(33);
    int tested = 0;
    for (int sample = 0; sample < 16; ++sample) {
      const Mat3 F1 = randomF(gen, sample % 4 == 3);
      const State s1 = step(m, F1, virgin(m)).state;
      // Further along the same path, turned by a random increment of 0.05.
      Mat3 F2 = F1;
      for (int a = 0; a < 9; ++a)
        F2[a] += 0.3 * (F1[a] - (a % 4 == 0 ? 1.0 : 0.0)) +
                 (sample % 4 == 3 && (a % 3 == 2 || a >= 6) ? 0.0 : 0.05 * entry(gen));
      const double alpha2 = alphaOf(step(m, F2, s1).state);
      if (!(alpha2 > alphaOf(s1) + 1e-4) || nearKnot(law.parameters, alpha2)) continue;
      expectTangent(m, F2, s1, law.label + " sample " + std::to_string(sample));
      ++tested;
    }
    EXPECT_GE(tested, 10) << law.label;
  }
  reportTangentError("plastic from a pre-strained state");
}

TEST(SimoMiehe, TangentMatchesCentralDifferencesInElasticUnloading) {
  for (const Law& law : plasticLaws()) {
    const SimoMiehe m(law.parameters);
    std::mt19937 gen(34);
    for (int sample = 0; sample < 8; ++sample) {
      const Mat3 F1 = randomF(gen, sample % 2 == 1);
      const State s1 = step(m, F1, virgin(m)).state;
      // b_e = F1 C_p^-1 F1^T = exp(2 eps_e); F2 = R A F1 with A = exp(-dev eps_e / 2) gives the
      // trial b_e R exp(2 eps_e - dev eps_e) R^T: half the deviator, inside the yield surface.
      const Mat3 be = tensor3::multiplyTranspose(tensor3::multiply(F1, inversePlastic(s1)), F1);
      std::array<double, 3> b;
      Mat3 Q;
      ASSERT_TRUE(tensor3::symmetricEigen(be, b, Q));
      const double meanLog = (std::log(b[0]) + std::log(b[1]) + std::log(b[2])) / 6.0;
      Mat3 A{};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          for (int a = 0; a < 3; ++a)
            A[i * 3 + j] +=
                std::exp(-0.5 * (0.5 * std::log(b[a]) - meanLog)) * Q[i * 3 + a] * Q[j * 3 + a];
      const Mat3 R = sample % 2 == 1 ? rotation({0, 0, 1}, 0.3 * sample)
                                     : rotation({1.0, 2.0, -0.5 * sample}, 0.2 + 0.1 * sample);
      const Mat3 F2 = tensor3::multiply(R, tensor3::multiply(A, F1));
      const Step r = step(m, F2, s1);
      EXPECT_EQ(r.state, s1) << law.label << " sample " << sample
                             << ": unloading changed the state";
      EXPECT_NEAR(vonMises(kirchhoff(r.out, F2)), 0.5 * m.yieldStress(alphaOf(s1)), 1e-10 * kYield)
          << law.label << " sample " << sample;
      expectTangent(m, F2, s1, law.label + " unloading sample " + std::to_string(sample));
    }
  }
  reportTangentError("elastic unloading");
}

TEST(SimoMiehe, TangentMatchesCentralDifferencesWithEqualPrincipalStretches) {
  const SimoMiehe hardening(linear(20.0)), perfect(linear(0.0)), curve(concaveCurve());
  const SimoMiehe elastic(linear(20.0, 1e3 * kE));
  const std::vector<const SimoMiehe*> laws = {&hardening, &perfect, &curve, &elastic};
  for (const SimoMiehe* m : laws) {
    const std::string name = m == &elastic ? "elastic" : m == &perfect ? "perfect" : "hardening";
    // Three equal stretches (elastic at every law: no deviator).
    for (double s : {1.0, 0.9, 1.2})
      expectTangent(*m, diagonal(s, s, s), virgin(*m), name + " hydrostatic " + std::to_string(s));
    // Uniaxial: two equal principal stretches, exactly, nearly (relative split 1e-9, 1e-7; 5e-4
    // is where the divided difference of ln switches to its series) and apart (1e-2).
    for (double s : {0.7, 1.3, 1.6})
      for (double split : {0.0, 1e-9, 1e-7, 5e-4, 1e-2}) {
        const double l = 1.01 / std::sqrt(s);
        const Mat3 F = diagonal(s, l, l * (1 + split));
        const std::string label =
            name + " uniaxial " + std::to_string(s) + " split " + std::to_string(split);
        expectTangent(*m, F, virgin(*m), label);
        // The same stretch turned: the eigenvectors are no longer the axes.
        const Mat3 Q = rotation({1, -1, 2}, 0.7);
        const Mat3 turned = tensor3::multiply(Q, tensor3::multiplyTranspose(F, Q));
        expectTangent(*m, turned, virgin(*m), label + " turned");
        // From a uniaxially pre-strained state (C_p^-1 with two equal entries), further along.
        const State s1 = step(*m, F, virgin(*m)).state;
        const double s2 = s > 1 ? s * 1.05 : s * 0.95;
        const Mat3 F2 = diagonal(s2, 1.01 / std::sqrt(s2), 1.01 / std::sqrt(s2));
        if (m != &elastic) {
          EXPECT_GT(alphaOf(step(*m, F2, s1).state), alphaOf(s1)) << label;
        }
        expectTangent(*m, F2, s1, label + " pre-strained");
      }
  }
  reportTangentError("equal principal stretches");
}

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
  J2SmallStrain::Parameters j2p;
  j2p.youngModulus = 200e3;
  j2p.poissonRatio = 0.3;
  j2p.yieldStress = 20.0 * scale;
  j2p.isotropicHardening = 5e3;
  const J2SmallStrain j2(j2p);
  SimoMiehe::Parameters smp;
  smp.youngModulus = j2p.youngModulus;
  smp.poissonRatio = j2p.poissonRatio;
  smp.yieldStress = j2p.yieldStress;
  smp.isotropicHardening = j2p.isotropicHardening;
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
