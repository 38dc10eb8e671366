// Pointwise contact laws (penalty, Lagrange, augmented Lagrangian): finite-difference checks of
// the Jacobian on every status piece, the frozen status/threshold seam of the algorithms, the
// sign conventions, a solved one-point problem and the registry.
#include "formulations/AugmentedLagrangian.hpp"
#include "formulations/ContactLaw.hpp"
#include "formulations/FormulationRegistry.hpp"
#include "formulations/Lagrange.hpp"
#include "formulations/Penalty.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace contactlab {
namespace {

const double kMu = 0.3;
const double kWeight = 0.7;

// Coefficients of moderate size so that central differences are accurate to ~1e-9.
std::unique_ptr<ContactLaw> makeLaw(const std::string& name) {
  if (name == "penalty") return std::make_unique<Penalty>(100.0, 50.0);
  if (name == "lagrange") return std::make_unique<Lagrange>(10.0, 5.0);
  return std::make_unique<AugmentedLagrangian>(10.0, 5.0);
}

const char* const kLawNames[] = {"penalty", "lagrange", "augmented-lagrangian"};

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
  LawInput in;
  in.weight = kWeight;
  in.nt = nt;
  in.mu = nt > 0 ? kMu : 0.0;
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

// --- 3. Signs and limits of the seed's convention ------------------------------------------

TEST(ContactLaw, SeparatedPointIsFreeAndExertsNoForce) {
  for (const char* name : kLawNames) {
    const auto law = makeLaw(name);
    for (int nt : {0, 1, 2}) {
      SCOPED_TRACE(std::string(name) + " nt=" + std::to_string(nt));
      LawInput in;
      in.weight = kWeight;
      in.nt = nt;
      in.mu = nt > 0 ? kMu : 0.0;
      in.gap = 0.05;
      in.p = 0.0;
      in.slip = {0.01, -0.02};
      in.Lambda = {0.4, 0.2};
      if (nt < 2) in.slip[1] = in.Lambda[1] = 0.0;
      LawOutput out;
      law->evaluate(in, out);
      EXPECT_EQ(out.status, ContactStatus::Free);
      EXPECT_EQ(out.pressure, 0.0);
      for (int i = 0; i <= nt; ++i)
        EXPECT_EQ(out.r[i], 0.0) << "displacement residual coefficient " << i;
      for (int k = 0; k < nt; ++k)
        EXPECT_EQ(out.tangentialTraction[k], 0.0);
    }
  }
}

// A body resting on its contact at zero gap under a load (load control): the first tangent
// needs the contact stiffness. Penalty took the open piece at g = 0 and the first Newton system
// had no normal stiffness at all (the run ended in max-iterations with no cause given).
TEST(ContactLaw, PenaltyTouchingPointIsClosedWithItsStiffness) {
  const auto law = makeLaw("penalty");  // eps_n = 100
  LawInput in;
  in.weight = kWeight;
  in.gap = 0.0;
  LawOutput out;
  law->evaluate(in, out);
  EXPECT_NE(out.status, ContactStatus::Free);
  EXPECT_EQ(out.pressure, 0.0);
  EXPECT_DOUBLE_EQ(out.J[0], kWeight * 100.0);
}

// A touching point whose gap is round-off (a mortar weighted gap of -3e-33 instead of 0) has a
// threshold of ~1e-28, not a pressure. The stick piece then put Lambda into the tangent through
// a column w * threshold wide, and the first Newton update of a frictional mortar Hertz roller
// set Lambda = 4e29 ("diverged"). Such a point takes the zero-threshold piece: its friction
// rows are w Lambda = 0, regular, as at an exact zero gap.
TEST(ContactLaw, RoundoffThresholdOfATouchingPointCarriesNoFriction) {
  for (const char* name : {"lagrange", "augmented-lagrangian"}) {
    const auto law = makeLaw(name);
    for (int nt : {1, 2}) {
      for (double gap : {0.0, -3.3e-33, -1e-20}) {
        SCOPED_TRACE(std::string(name) + " nt=" + std::to_string(nt) +
                     " gap=" + std::to_string(gap));
        LawInput in;
        in.weight = kWeight;
        in.nt = nt;
        in.mu = kMu;
        in.gap = gap;
        LawOutput out;
        law->evaluate(in, out);
        const int n = law->size(nt), lam = 2 + nt;
        EXPECT_NE(out.status, ContactStatus::Free);
        for (int k = 0; k < nt; ++k) {
          EXPECT_EQ(out.J[(lam + k) * n + lam + k], kWeight) << "friction row " << k;
          EXPECT_EQ(out.tangentialTraction[k], 0.0);
        }
      }
    }
    // A real (small) penetration keeps its friction: the cutoff is round-off, not physics.
    LawInput in;
    in.weight = kWeight;
    in.nt = 1;
    in.mu = kMu;
    in.gap = -1e-6;
    LawOutput out;
    law->evaluate(in, out);
    EXPECT_GT(out.threshold, 0.0) << name;
  }
}

// The cut is a gap's round-off, not a pressure: with an augmentation of 1e8 E/h (the extremes
// study's pad: E/h = 20, c = 2e9, tributary length 0.05) a converged point's pressure 0.01 is
// a real one and keeps its friction; at a cut of 1e-8 h it fell below c 1e-8 h = 1 and the
// dragged pad slid without friction, "converged".
TEST(ContactLaw, ALargeCoefficientKeepsTheFrictionOfARealPressure) {
  for (const char* name : {"lagrange", "augmented-lagrangian"}) {
    SCOPED_TRACE(name);
    std::unique_ptr<ContactLaw> law;
    if (std::string(name) == "lagrange")
      law = std::make_unique<Lagrange>(2e9, 100.0);
    else
      law = std::make_unique<AugmentedLagrangian>(2e9, 100.0);
    LawInput in;
    in.weight = 0.05;
    in.nt = 1;
    in.mu = 0.45;
    in.gap = 0.0;
    in.p = 0.01;
    in.slip = {0.048, 0.0};  // dragged far beyond the stick cone
    LawOutput out;
    law->evaluate(in, out);
    EXPECT_NEAR(out.threshold, 0.45 * 0.01, 1e-12);
    EXPECT_EQ(out.status, ContactStatus::Slip);
    // Lagrange's traction is its multiplier Lambda (0 here); the augmented one projects.
    if (std::string(name) == "augmented-lagrangian") {
      EXPECT_NEAR(std::abs(out.tangentialTraction[0]), 0.45 * 0.01, 1e-12);
    }
  }
}

TEST(ContactLaw, ClosedPointUnderCompressionTransmitsThePressure) {
  for (const char* name : {"lagrange", "augmented-lagrangian"}) {
    const auto law = makeLaw(name);
    for (int nt : {0, 1, 2}) {
      SCOPED_TRACE(std::string(name) + " nt=" + std::to_string(nt));
      LawInput in;
      in.weight = kWeight;
      in.nt = nt;
      in.mu = nt > 0 ? kMu : 0.0;
      in.gap = 0.0;
      in.p = 1.5;
      LawOutput out;
      law->evaluate(in, out);
      EXPECT_NE(out.status, ContactStatus::Free);
      EXPECT_DOUBLE_EQ(out.pressure, 1.5);
      // R_u += -p dg: the pressure pushes the slave away from the master (along +g).
      EXPECT_DOUBLE_EQ(out.r[0], -kWeight * 1.5);
      EXPECT_NEAR(out.r[1 + nt], 0.0, 1e-15);  // the gap condition g = 0 holds
    }
  }
  const auto penalty = makeLaw("penalty");
  LawInput in;
  in.weight = kWeight;
  in.gap = -0.02;
  LawOutput out;
  penalty->evaluate(in, out);
  EXPECT_NE(out.status, ContactStatus::Free);
  EXPECT_DOUBLE_EQ(out.pressure, 100.0 * 0.02);
  EXPECT_DOUBLE_EQ(out.r[0], -kWeight * 100.0 * 0.02);
}

TEST(ContactLaw, SlidingPointIsResistedByCoulombFriction) {
  const auto law = makeLaw("augmented-lagrangian");
  for (double direction : {1.0, -1.0}) {
    LawInput in;
    in.weight = kWeight;
    in.nt = 1;
    in.mu = kMu;
    in.gap = 0.0;
    in.p = 2.0;
    in.Lambda = {direction};      // slip direction
    in.slip = {direction * 0.1};  // slipping along it
    LawOutput out;
    law->evaluate(in, out);
    EXPECT_EQ(out.status, ContactStatus::Slip);
    EXPECT_DOUBLE_EQ(out.pressure, 2.0);
    EXPECT_DOUBLE_EQ(out.threshold, kMu * 2.0);
    EXPECT_LT(out.tangentialTraction[0] * direction, 0.0);  // opposes the slip
    EXPECT_DOUBLE_EQ(std::abs(out.tangentialTraction[0]), kMu * out.pressure);
    // Equilibrium of the slave: R_u = k_v v, the resistance acts along the slip.
    EXPECT_DOUBLE_EQ(out.r[1], kWeight * kMu * 2.0 * direction);
    EXPECT_NEAR(out.r[3], 0.0, 1e-15);  // Lambda is the slip direction
  }
  // A small slip with ||Lambda|| < 1 sticks; the traction is mu p Lambda, below mu p.
  LawInput in;
  in.weight = kWeight;
  in.nt = 2;
  in.mu = kMu;
  in.gap = 0.0;
  in.p = 2.0;
  in.Lambda = {0.3, -0.4};
  in.slip = {1e-3, 1e-3};
  LawOutput out;
  law->evaluate(in, out);
  EXPECT_EQ(out.status, ContactStatus::Stick);
  const double t = std::hypot(out.tangentialTraction[0], out.tangentialTraction[1]);
  EXPECT_LT(t, kMu * out.pressure);
  // The stick residual asks for v = 0: r_Lambda = -r_t v.
  EXPECT_NEAR(out.r[4], -kWeight * 5.0 * 1e-3, 1e-14);

  // Penalty: the resistance grows with the elastic slip, then saturates at mu p.
  const auto penalty = makeLaw("penalty");
  LawInput pin;
  pin.weight = 1.0;
  pin.nt = 1;
  pin.mu = kMu;
  pin.gap = -0.01;  // p = 1, threshold 0.3
  pin.slip = {1e-3};
  penalty->evaluate(pin, out);
  EXPECT_EQ(out.status, ContactStatus::Stick);
  EXPECT_DOUBLE_EQ(out.tangentialTraction[0], -50.0 * 1e-3);
  pin.slip = {-1.0};
  penalty->evaluate(pin, out);
  EXPECT_EQ(out.status, ContactStatus::Slip);
  EXPECT_DOUBLE_EQ(out.tangentialTraction[0], kMu * 1.0);
}

// --- 4. A solved one-point problem ----------------------------------------------------------
// A slave point on springs (normal k_n, tangential k_t) under a load (f_n toward a rigid plane
// at initial distance g0, f_t along it). Unknowns: displacement u = (u_n, u_t) (u_n toward the
// plane) and the law's multipliers. g = g0 - u_n, v = u_t (slip from a rest state), so
// B = diag(-1, 1) and R_u = K u - f + B^T r_k, R_m = r_m, from rest (all zero). Exact multipliers:
// u_n = g0, p = f_n - k_n g0; stick (f_t < mu p): u_t = 0, Lambda = f_t / (mu p); slip: k_t u_t =
// f_t - mu p.

struct OnePointResult {
  double un = 0, ut = 0, pressure = 0, Lambda = 0;
  ContactStatus status = ContactStatus::Free;
  int iterations = 0;
};

std::vector<double> solveDense(std::vector<double> A, std::vector<double> b) {
  const int n = static_cast<int>(b.size());
  for (int c = 0; c < n; ++c) {
    int piv = c;
    for (int r = c + 1; r < n; ++r)
      if (std::abs(A[r * n + c]) > std::abs(A[piv * n + c])) piv = r;
    for (int k = 0; k < n; ++k)
      std::swap(A[c * n + k], A[piv * n + k]);
    std::swap(b[c], b[piv]);
    for (int r = c + 1; r < n; ++r) {
      const double f = A[r * n + c] / A[c * n + c];
      for (int k = c; k < n; ++k)
        A[r * n + k] -= f * A[c * n + k];
      b[r] -= f * b[c];
    }
  }
  std::vector<double> x(n);
  for (int r = n - 1; r >= 0; --r) {
    double s = b[r];
    for (int k = r + 1; k < n; ++k)
      s -= A[r * n + k] * x[k];
    x[r] = s / A[r * n + r];
  }
  return x;
}

const double kKn = 100.0, kKt = 50.0, kG0 = 0.01, kFn = 3.0;

OnePointResult solveOnePoint(const ContactLaw& law, double ft) {
  const int nt = 1, n = law.size(nt);
  const double B[2] = {-1.0, 1.0}, K[2] = {kKn, kKt}, f[2] = {kFn, ft};
  std::vector<double> x(n, 0.0);  // (u_n, u_t, [p, Lambda])
  OnePointResult res;
  for (int it = 1; it <= 50; ++it) {
    LawInput in;
    in.weight = 1.0;
    in.nt = nt;
    in.mu = kMu;
    in.gap = kG0 - x[0];
    in.slip = {x[1], 0.0};
    if (law.hasMultipliers()) {
      in.p = x[2];
      in.Lambda = {x[3], 0.0};
    }
    LawOutput out;
    law.evaluate(in, out);
    std::vector<double> R(n), A(n * n);
    for (int i = 0; i < n; ++i) {
      const double Bi = i < 2 ? B[i] : 1.0;
      R[i] = (i < 2 ? K[i] * x[i] - f[i] : 0.0) + Bi * out.r[i];
      for (int j = 0; j < n; ++j) {
        const double Bj = j < 2 ? B[j] : 1.0;
        A[i * n + j] = (i == j && i < 2 ? K[i] : 0.0) + Bi * out.J[i * n + j] * Bj;
      }
    }
    double norm = 0;
    for (double r : R)
      norm = std::isfinite(r) ? std::max(norm, std::abs(r)) : HUGE_VAL;
    res = {x[0], x[1], out.pressure, law.hasMultipliers() ? x[3] : 0.0, out.status, it};
    if (norm < 1e-12) return res;
    const std::vector<double> dx = solveDense(A, R);
    for (int i = 0; i < n; ++i)
      x[i] -= dx[i];
  }
  res.iterations = -1;
  return res;
}

TEST(ContactLaw, NewtonSolvesOnePointProblemWithMultipliers) {
  const double p = kFn - kKn * kG0;  // 2
  for (const char* name : {"lagrange", "augmented-lagrangian"}) {
    const auto law = makeLaw(name);
    SCOPED_TRACE(name);
    // Stick: f_t = 0.3 < mu p = 0.6.
    OnePointResult stick = solveOnePoint(*law, 0.3);
    ASSERT_GT(stick.iterations, 0) << "Newton did not converge";
    EXPECT_LE(stick.iterations, 10);
    EXPECT_EQ(stick.status, ContactStatus::Stick);
    EXPECT_NEAR(stick.un, kG0, 1e-12);
    EXPECT_NEAR(stick.pressure, p, 1e-10);
    EXPECT_NEAR(stick.ut, 0.0, 1e-12);
    EXPECT_NEAR(stick.Lambda, 0.3 / (kMu * p), 1e-10);
    // Slip: f_t = 1 > 0.6.
    OnePointResult slip = solveOnePoint(*law, 1.0);
    ASSERT_GT(slip.iterations, 0) << "Newton did not converge";
    EXPECT_LE(slip.iterations, 10);
    EXPECT_EQ(slip.status, ContactStatus::Slip);
    EXPECT_NEAR(slip.un, kG0, 1e-12);
    EXPECT_NEAR(slip.pressure, p, 1e-10);
    EXPECT_NEAR(slip.ut, (1.0 - kMu * p) / kKt, 1e-12);
    EXPECT_NEAR(slip.Lambda, 1.0, 1e-12);
  }
}

TEST(ContactLaw, NewtonSolvesOnePointProblemWithPenalty) {
  const auto law = makeLaw("penalty");  // eps_n = 100, eps_t = 50
  const double epsN = 100.0, epsT = 50.0;
  const double un = (kFn + epsN * kG0) / (kKn + epsN), p = epsN * (un - kG0);
  OnePointResult stick = solveOnePoint(*law, 0.3);  // q = 0.15 < mu p = 0.3
  ASSERT_GT(stick.iterations, 0);
  EXPECT_EQ(stick.status, ContactStatus::Stick);
  EXPECT_NEAR(stick.un, un, 1e-12);
  EXPECT_NEAR(stick.pressure, p, 1e-10);
  EXPECT_NEAR(stick.ut, 0.3 / (kKt + epsT), 1e-12);
  OnePointResult slip = solveOnePoint(*law, 1.0);
  ASSERT_GT(slip.iterations, 0);
  EXPECT_EQ(slip.status, ContactStatus::Slip);
  EXPECT_NEAR(slip.un, un, 1e-12);
  EXPECT_NEAR(slip.ut, (1.0 - kMu * p) / kKt, 1e-12);
}

// --- 5. Registry ---------------------------------------------------------------------------

TEST(FormulationRegistry, DefaultsOfRequiredCoefficientsAreRejectedByName) {
  registerFormulations();
  registerFormulations();  // idempotent
  auto& registry = formulationRegistry();
  EXPECT_EQ(registry.names().size(), 4u);
  for (const char* name : kLawNames)
    ASSERT_TRUE(registry.has(name)) << name;

  const std::pair<const char*, const char*> required[] = {
      {"penalty", "Normal Penalty"},
      {"augmented-lagrangian", "Normal Augmentation"},
      {"normal-field-augmented-lagrangian", "Normal Augmentation"}};
  for (const auto& [name, key] : required) {
    const auto& entry = registry.get(name);
    const auto defaults = entry.validParameters();
    try {
      entry.build(*defaults);
      ADD_FAILURE() << name << " built with its default (zero) coefficients";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }

  const auto& lagrange = registry.get("lagrange");
  std::unique_ptr<ContactLaw> law;
  ASSERT_NO_THROW(law = lagrange.build(*lagrange.validParameters()));
  EXPECT_EQ(law->name(), "lagrange");
  EXPECT_TRUE(law->hasMultipliers());

  // With the required coefficient given, the unused tangential one may stay at its default.
  for (const auto& [name, key] : required) {
    const auto& entry = registry.get(name);
    Teuchos::ParameterList params(*entry.validParameters());
    params.set(key, 10.0);
    std::unique_ptr<ContactLaw> built;
    ASSERT_NO_THROW(built = entry.build(params)) << name;
    EXPECT_EQ(built->name(), name);
  }
  EXPECT_THROW(registry.get("no-such-law"), std::invalid_argument);
}

}  // namespace
}  // namespace contactlab
