#pragma once
// Helpers shared by the simo-miehe tests: the laws under test (linear, perfect and tabulated
// hardening), one evaluation with its state, the Kirchhoff and von Mises stresses, and the
// central-difference tangent check whose worst error each tangent test reports.
#include "tests/unit/materials/MaterialTestSupport.hpp"

#include "core/materials/SimoMiehe.hpp"
#include "core/materials/Tensor3.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <string>
#include <vector>

namespace contactlab::test::simo_miehe {

using tensor3::Mat3;
using State = std::array<double, SimoMiehe::kStateSize>;

// Yield strain 2e-3: every random F of the tangent tests (|F - I| >= 0.05) yields.
constexpr double kE = 200.0, kNu = 0.3, kYield = 0.4;
// Relative tolerance of the central-difference checks (h = 1e-6 on F ~ 1).
constexpr double kTangentTolerance = 1e-7;

inline SimoMiehe::Parameters linear(double H, double yield = kYield) {
  SimoMiehe::Parameters p;
  p.youngModulus = kE;
  p.poissonRatio = kNu;
  p.yieldStress = yield;
  p.isotropicHardening = H;
  return p;
}

// Hardening that saturates (slopes 10, 1.25, 0.1, then 0.1 on) and one that stiffens (1, 3).
inline SimoMiehe::Parameters concaveCurve() {
  SimoMiehe::Parameters p = linear(0.0);
  p.hardeningStrains = {0.0, 0.02, 0.1, 0.3};
  p.hardeningStresses = {kYield, 0.6, 0.7, 0.72};
  return p;
}

inline SimoMiehe::Parameters convexCurve() {
  SimoMiehe::Parameters p = linear(0.0);
  p.hardeningStrains = {0.0, 0.05, 0.1};
  p.hardeningStresses = {kYield, 0.45, 0.6};
  return p;
}

struct Law {
  std::string label;
  SimoMiehe::Parameters parameters;
};

inline std::vector<Law> plasticLaws() {
  return {{"linear H = 20", linear(20.0)},
          {"perfectly plastic", linear(0.0)},
          {"tabulated concave", concaveCurve()},
          {"tabulated convex", convexCurve()}};
}

inline State virgin(const SimoMiehe& m) {
  State s;
  s.fill(7.0);
  m.initializeState(s.data());
  return s;
}

inline double alphaOf(const State& s) {
  return s[SimoMiehe::kEquivalentPlasticStrain];
}

struct Step {
  MaterialOutput out;
  State state;
};

inline Step step(const SimoMiehe& m, const Mat3& F, const State& stateOld) {
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

inline Mat3 inversePlastic(const State& s) {
  const double* c = s.data() + SimoMiehe::kInversePlasticStrain;
  return {c[0], c[3], c[5], c[3], c[1], c[4], c[5], c[4], c[2]};
}

// Kirchhoff stress tau = P F^T and its von Mises value sqrt(3/2) |dev tau|.
inline Mat3 kirchhoff(const MaterialOutput& out, const Mat3& F) {
  return tensor3::multiplyTranspose(out.P, F);
}

inline double vonMises(const Mat3& tau) {
  const double p = tensor3::trace(tau) / 3.0;
  double s2 = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double d = tau[i * 3 + j] - (i == j ? p : 0.0);
      s2 += d * d;
    }
  return std::sqrt(1.5 * s2);
}

// The largest relative central-difference error of the current tangent test, printed (and
// reset) at its end: the figures the commit reports.
inline double worstTangentError = 0.0;

inline void expectTangent(const SimoMiehe& m, const Mat3& F, const State& stateOld,
                          const std::string& label) {
  const double err = dPdFError(m, F, stateOld.data());
  worstTangentError = std::max(worstTangentError, err);
  EXPECT_LT(err, kTangentTolerance) << label;
}

inline void reportTangentError(const std::string& test) {
  std::cout << test << ": largest relative central-difference error of dP/dF " << worstTangentError
            << "\n";
  worstTangentError = 0.0;
}

// True when alpha lies within `margin` of a knot of the curve (a kink of the yield stress, where
// central differences straddle two slopes).
inline bool nearKnot(const SimoMiehe::Parameters& p, double alpha, double margin = 1e-4) {
  for (double s : p.hardeningStrains)
    if (std::abs(alpha - s) < margin) return true;
  return false;
}

}  // namespace contactlab::test::simo_miehe
