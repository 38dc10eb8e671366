// simo-miehe: the state layout, the reference configuration, and the consistent dP/dF against
// central differences (elastic, plastic from the virgin and from a pre-strained state, elastic
// unloading, linear / perfect / tabulated hardening, equal and near-equal principal stretches)
// with its major symmetry.
#include "tests/unit/materials/SimoMieheTestSupport.hpp"

#include "core/materials/SimoMiehe.hpp"
#include "core/materials/Tensor3.hpp"

#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <string>
#include <vector>

namespace contactlab {
namespace {

using namespace test;
using namespace test::simo_miehe;

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

}  // namespace
}  // namespace contactlab
