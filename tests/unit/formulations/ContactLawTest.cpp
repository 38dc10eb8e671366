// Pointwise contact laws (penalty, Lagrange, augmented Lagrangian): the sign conventions and
// limits (separation, touching, round-off gaps, compression, Coulomb friction) and a solved
// one-point problem. The Jacobian checks are ContactLawJacobianTest.cpp.
#include "tests/unit/formulations/ContactLawTestSupport.hpp"

#include "formulations/AugmentedLagrangian.hpp"
#include "formulations/ContactLaw.hpp"
#include "formulations/Lagrange.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>

namespace contactlab {
namespace {

using namespace test;

// --- 3. Signs and limits of the seed's convention ------------------------------------------

TEST(ContactLaw, SeparatedPointIsFreeAndExertsNoForce) {
  for (const char* name : kLawNames) {
    const auto law = makeLaw(name);
    for (int nt : {0, 1, 2}) {
      SCOPED_TRACE(std::string(name) + " nt=" + std::to_string(nt));
      LawInput in = pointInput(nt, 0.05);
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
  const LawInput in = pointInput(0, 0.0);
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
        const LawInput in = pointInput(nt, gap);  // nt > 0: friction kMu
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
    const LawInput in = pointInput(1, -1e-6);
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
      const LawInput in = pointInput(nt, 0.0, 1.5);
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
  const LawInput in = pointInput(0, -0.02);
  LawOutput out;
  penalty->evaluate(in, out);
  EXPECT_NE(out.status, ContactStatus::Free);
  EXPECT_DOUBLE_EQ(out.pressure, 100.0 * 0.02);
  EXPECT_DOUBLE_EQ(out.r[0], -kWeight * 100.0 * 0.02);
}

TEST(ContactLaw, SlidingPointIsResistedByCoulombFriction) {
  const auto law = makeLaw("augmented-lagrangian");
  for (double direction : {1.0, -1.0}) {
    LawInput in = pointInput(1, 0.0, 2.0);
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
  LawInput in = pointInput(2, 0.0, 2.0);
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

}  // namespace
}  // namespace contactlab
