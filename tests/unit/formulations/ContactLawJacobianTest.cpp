// Pointwise contact laws (penalty, Lagrange, augmented Lagrangian): finite-difference checks of
// the Jacobian on every status piece (and that the check catches a wrong entry), and the frozen
// status/threshold seam of the algorithms.
#include "tests/unit/formulations/ContactLawTestSupport.hpp"

#include "formulations/ContactLaw.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace contactlab {
namespace {

using namespace test;

// The law variables (g, v_1..v_nt, [p, Lambda_1..Lambda_nt]) as a flat vector and back.
std::vector<double> packVariables(const ContactLaw& law, const LawInput& in) {
  const int nt = in.nt;
  std::vector<double> x(law.size(nt));
  x[0] = in.gap;
  for (int k = 0; k < nt; ++k)
    x[1 + k] = in.slip[k];
  if (law.hasMultipliers()) {
    x[1 + nt] = in.p;
    for (int k = 0; k < nt; ++k)
      x[2 + nt + k] = in.Lambda[k];
  }
  return x;
}

LawInput unpackVariables(const ContactLaw& law, LawInput in, const std::vector<double>& x) {
  const int nt = in.nt;
  in.gap = x[0];
  for (int k = 0; k < nt; ++k)
    in.slip[k] = x[1 + k];
  if (law.hasMultipliers()) {
    in.p = x[1 + nt];
    for (int k = 0; k < nt; ++k)
      in.Lambda[k] = x[2 + nt + k];
  }
  return in;
}

// Central differences of r against J, entry by entry, |J - fd| <= 1e-6 (1 + |fd|). The status
// must not change under the perturbations (the state is far from every switching boundary).
::testing::AssertionResult jacobianMatchesFiniteDifferences(const ContactLaw& law,
                                                            const LawInput& in) {
  const int n = law.size(in.nt);
  LawOutput base;
  law.evaluate(in, base);
  const std::vector<double> x0 = packVariables(law, in);
  std::ostringstream errors;
  bool ok = true;
  for (int j = 0; j < n; ++j) {
    const double h = 1e-6 * std::max(1.0, std::abs(x0[j]));
    std::vector<double> xp = x0, xm = x0;
    xp[j] += h;
    xm[j] -= h;
    LawOutput op, om;
    law.evaluate(unpackVariables(law, in, xp), op);
    law.evaluate(unpackVariables(law, in, xm), om);
    if (op.status != base.status || om.status != base.status) {
      ok = false;
      errors << " status changes when perturbing variable " << j << ";";
    }
    for (int i = 0; i < n; ++i) {
      const double fd = (op.r[i] - om.r[i]) / (2 * h);
      const double Jij = base.J[i * n + j];
      if (!(std::abs(Jij - fd) <= 1e-6 * (1.0 + std::abs(fd)))) {
        ok = false;
        errors << " J(" << i << "," << j << ") = " << Jij << " but finite difference " << fd << ";";
      }
    }
  }
  // Entries beyond n x n must stay untouched (the assembly reads only the n x n block).
  for (int i = n * n; i < kMaxLawVariables * kMaxLawVariables; ++i)
    if (base.J[i] != 0.0) {
      ok = false;
      errors << " J storage entry " << i << " beyond n x n is nonzero;";
    }
  if (ok) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << law.name() << " nt=" << in.nt << ":" << errors.str();
}

enum class State { Free, Stick, Slip };

const char* stateName(State s) {
  return s == State::Free ? "free" : s == State::Stick ? "stick" : "slip";
}

// States far from the switching boundaries, for the given law family:
//   penalty: closed iff g < 0; stick iff ||q_old + eps_t v|| < mu eps_n (-g) (= 0.3 here);
//   multipliers: closed iff p - c g >= 0 (c = 10); stick iff ||Lambda + c_t v|| < 1 (c_t = 5).
LawInput makeState(const ContactLaw& law, int nt, State s) {
  LawInput in = pointInput(nt, 0.0);
  if (!law.hasMultipliers()) {
    switch (s) {
      case State::Free:  // g > 0
        in.gap = 0.02;
        in.slip = {0.01, -0.02};
        in.tangentialOld = {0.1, 0.05};
        break;
      case State::Stick:  // pressure 1, threshold 0.3, trial (0.1, 0.07)
        in.gap = -0.01;
        in.slip = {0.001, 0.002};
        in.tangentialOld = {0.05, -0.03};
        break;
      case State::Slip:  // trial (1.1, -0.45), ||.|| = 1.19 > 0.3
        in.gap = -0.01;
        in.slip = {0.02, -0.01};
        in.tangentialOld = {0.1, 0.05};
        break;
    }
  } else {
    switch (s) {
      case State::Free:  // p^ = 0.05 - 0.2 = -0.15
        in.gap = 0.02;
        in.p = 0.05;
        in.slip = {0.01, 0.02};
        in.Lambda = {0.2, -0.1};
        break;
      case State::Stick:  // p^ = 1.99, Lambda^ = (0.35, -0.1)
        in.gap = 0.001;
        in.p = 2.0;
        in.slip = {0.01, 0.02};
        in.Lambda = {0.3, -0.2};
        break;
      case State::Slip:  // p^ = 2.01, Lambda^ = (1.1, 0.25)
        in.gap = -0.001;
        in.p = 2.0;
        in.slip = {0.1, -0.05};
        in.Lambda = {0.6, 0.5};
        break;
    }
  }
  if (nt < 2) {  // unused components stay zero
    in.slip[1] = 0.0;
    in.Lambda[1] = 0.0;
    in.tangentialOld[1] = 0.0;
  }
  return in;
}

ContactStatus expectedStatus(int nt, State s) {
  if (s == State::Free) return ContactStatus::Free;
  if (nt == 0) return ContactStatus::Stick;  // closed without friction reports Stick
  return s == State::Stick ? ContactStatus::Stick : ContactStatus::Slip;
}

// --- 1. Finite-difference tangent on each status piece --------------------------------------

TEST(ContactLaw, JacobianMatchesFiniteDifferencesOnEveryPiece) {
  for (const char* name : kLawNames) {
    const auto law = makeLaw(name);
    for (int nt : {0, 1, 2}) {
      for (State s : {State::Free, State::Stick, State::Slip}) {
        if (nt == 0 && s == State::Slip) continue;  // no slip piece without friction
        SCOPED_TRACE(std::string(name) + " nt=" + std::to_string(nt) + " " + stateName(s));
        const LawInput in = makeState(*law, nt, s);
        LawOutput out;
        law->evaluate(in, out);
        EXPECT_EQ(out.status, expectedStatus(nt, s));
        EXPECT_TRUE(jacobianMatchesFiniteDifferences(*law, in));
      }
    }
  }
}

// The checker itself detects a wrong entry: a law whose J has one entry with the wrong sign.
class SignFlipped : public ContactLaw {
 public:
  SignFlipped(std::unique_ptr<ContactLaw> law, int entry) : law_(std::move(law)), entry_(entry) {}
  std::string name() const override { return law_->name() + "-flipped"; }
  bool hasMultipliers() const override { return law_->hasMultipliers(); }
  double normalCoefficient() const override { return law_->normalCoefficient(); }
  bool symmetricJacobian(int) const override { return false; }
  void evaluate(const LawInput& in, LawOutput& out) const override {
    law_->evaluate(in, out);
    const int n = size(in.nt);
    out.J[(entry_ / n) * n + entry_ % n] *= -1.0;
  }

 private:
  std::unique_ptr<ContactLaw> law_;
  int entry_;
};

TEST(ContactLaw, FiniteDifferenceCheckDetectsEveryWrongNonzeroEntry) {
  int detected = 0;
  for (const char* name : kLawNames) {
    const auto reference = makeLaw(name);
    for (State s : {State::Stick, State::Slip}) {
      const LawInput in = makeState(*reference, 2, s);
      LawOutput out;
      reference->evaluate(in, out);
      const int n = reference->size(2);
      for (int e = 0; e < n * n; ++e) {
        if (out.J[e] == 0.0) continue;
        SignFlipped flipped(makeLaw(name), e);
        EXPECT_FALSE(jacobianMatchesFiniteDifferences(flipped, in))
            << name << " " << stateName(s) << " entry " << e;
        ++detected;
      }
    }
  }
  EXPECT_GT(detected, 30);
}

// --- 2. The frozen seam -------------------------------------------------------------------

// A law that says its Jacobian is symmetric (the linear solver then takes the tangent as such:
// mumps Mode automatic) has J = J^T on every piece: open, closed, frozen, forced, scaled.
TEST(ContactLaw, JacobiansSaidSymmetricAreSymmetricOnEveryPiece) {
  int checked = 0;
  for (const char* name : kLawNames) {
    const auto law = makeLaw(name);
    for (int nt : {0, 1, 2}) {
      EXPECT_EQ(law->symmetricJacobian(nt), nt == 0 && std::string(name) != "lagrange") << name;
      if (!law->symmetricJacobian(nt)) continue;
      for (double gap : {0.05, 0.0, -0.02})
        for (double p : {0.0, 0.3})
          for (int frozen : {-1, 0, 1, 3}) {
            LawInput in;
            in.weight = kWeight;
            in.nt = nt;
            in.gap = gap;
            in.p = p;
            in.frozenStatus = frozen;
            in.coefficientScale = frozen == 3 ? 10.0 : 1.0;
            LawOutput out;
            law->evaluate(in, out);
            const int n = law->size(nt);
            for (int i = 0; i < n; ++i)
              for (int j = 0; j < n; ++j)
                EXPECT_EQ(out.J[i * n + j], out.J[j * n + i])
                    << name << " gap " << gap << " p " << p << " frozen " << frozen;
            ++checked;
          }
    }
  }
  EXPECT_EQ(checked, 2 * 3 * 2 * 4);
}

TEST(ContactLaw, FrozenStatusIsReportedAndJacobianStaysExact) {
  for (const char* name : kLawNames) {
    const auto law = makeLaw(name);
    for (int nt : {0, 1, 2}) {
      for (State s : {State::Free, State::Stick, State::Slip}) {
        if (nt == 0 && s == State::Slip) continue;
        for (int frozen : {0, 1, 2}) {
          SCOPED_TRACE(std::string(name) + " nt=" + std::to_string(nt) + " " + stateName(s) +
                       " frozen=" + std::to_string(frozen));
          LawInput in = makeState(*law, nt, s);
          in.frozenStatus = frozen;
          LawOutput out;
          law->evaluate(in, out);
          // Without friction there is no slip piece: a frozen "slip" is reported as closed.
          const ContactStatus expected =
              nt == 0 && frozen == 2 ? ContactStatus::Stick : static_cast<ContactStatus>(frozen);
          if (nt > 0 && frozen > 0 && s == State::Free && law->hasMultipliers() &&
              out.threshold <= 0) {
            // Frozen closed with a non-positive threshold (here p^ < 0): the law takes its
            // no-friction branch (Lambda = 0) and reports a closed status without stick/slip.
            EXPECT_NE(out.status, ContactStatus::Free);
          } else {
            EXPECT_EQ(out.status, expected);
          }
          EXPECT_TRUE(jacobianMatchesFiniteDifferences(*law, in));
        }
      }
    }
  }
}

// Frozen "closed, friction follows the iterate" (status 3, the contact fixed point and the
// forced cycling treatment): closed, with the natural stick/slip, and an exact Jacobian.
TEST(ContactLaw, FrozenClosedLetsFrictionFollowTheIterate) {
  for (const char* name : kLawNames) {
    const auto law = makeLaw(name);
    for (State s : {State::Stick, State::Slip}) {
      SCOPED_TRACE(std::string(name) + " " + stateName(s));
      LawInput in = makeState(*law, 1, s);
      LawOutput natural, frozen;
      law->evaluate(in, natural);
      in.frozenStatus = 3;
      law->evaluate(in, frozen);
      EXPECT_EQ(frozen.status, natural.status);
      EXPECT_TRUE(jacobianMatchesFiniteDifferences(*law, in));
    }
  }
}

// The automatic cycling treatment's local scale s on the coefficients is the law built with
// s times them (penalty excepted: its coefficients are the model, and it is never scaled).
TEST(ContactLaw, CoefficientScaleEqualsScaledCoefficients) {
  const AugmentedLagrangian al(10.0, 5.0), al10(100.0, 50.0);
  const Lagrange lg(10.0, 5.0), lg10(100.0, 50.0);
  const std::pair<const ContactLaw*, const ContactLaw*> pairs[] = {{&al, &al10}, {&lg, &lg10}};
  for (const auto& [law, scaled] : pairs) {
    for (State s : {State::Free, State::Stick, State::Slip}) {
      SCOPED_TRACE(law->name() + " " + stateName(s));
      LawInput in = makeState(*law, 1, s);
      LawOutput expected, got;
      scaled->evaluate(in, expected);
      in.coefficientScale = 10.0;
      law->evaluate(in, got);
      EXPECT_EQ(got.status, expected.status);
      for (int i = 0; i < law->size(1); ++i)
        EXPECT_NEAR(got.r[i], expected.r[i], 1e-12 * (1 + std::abs(expected.r[i])));
      EXPECT_NEAR(got.indicator, expected.indicator, 1e-12 * (1 + std::abs(expected.indicator)));
    }
  }
}

TEST(ContactLaw, FrozenThresholdDecouplesTangentialRowsFromPressure) {
  const double frozen = 0.25;
  for (const char* name : kLawNames) {
    const auto law = makeLaw(name);
    for (int nt : {1, 2}) {
      for (State s : {State::Stick, State::Slip}) {
        SCOPED_TRACE(std::string(name) + " nt=" + std::to_string(nt) + " " + stateName(s));
        LawInput in = makeState(*law, nt, s);
        LawOutput free;
        law->evaluate(in, free);
        in.frozenThreshold = frozen;
        LawOutput out;
        law->evaluate(in, out);
        const int n = law->size(nt), p = 1 + nt;
        EXPECT_EQ(out.threshold, frozen);
        for (int k = 0; k < nt; ++k) {
          const int v = 1 + k;
          EXPECT_EQ(out.J[v * n + 0], 0.0) << "d r_v" << k << " / dg";
          if (law->hasMultipliers()) {
            EXPECT_EQ(out.J[v * n + p], 0.0) << "d r_v" << k << " / dp";
          }
          // r_v is the threshold times a direction that does not depend on it, so it scales.
          if (name == std::string("penalty") && s == State::Stick) {
            EXPECT_NEAR(out.r[v], free.r[v], 1e-14);  // stick: q = trial, no threshold
          } else {
            EXPECT_NEAR(out.r[v], free.r[v] * frozen / free.threshold, 1e-12);
          }
        }
        EXPECT_TRUE(jacobianMatchesFiniteDifferences(*law, in));
      }
    }
  }
}

}  // namespace
}  // namespace contactlab
