// The multiplier rows of a law with multipliers are lengths and numbers (w g, w c_t v, a
// direction error times w), not forces; LawOutput::normalRowForce and frictionRowForce weigh
// each as the force it stands for, so that Newton's convergence test sees a violated contact
// equation (code_aster SSNV128: stick points 40 um slipped passed as converged).
#include "formulations/AugmentedLagrangian.hpp"
#include "formulations/ContactLaw.hpp"
#include "formulations/Lagrange.hpp"
#include "formulations/Penalty.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <string>

namespace contactlab {
namespace {

constexpr double kStiffness = 1e6;  // E / h
constexpr double kCn = 10.0, kCt = 5.0;

std::unique_ptr<ContactLaw> makeLaw(const std::string& name) {
  if (name == "lagrange") return std::make_unique<Lagrange>(kCn, kCt);
  return std::make_unique<AugmentedLagrangian>(kCn, kCt);
}

LawInput point(double gap, double p, double Lambda, double slip) {
  LawInput in;
  in.weight = 0.5;
  in.mu = 0.3;
  in.nt = 1;
  in.gap = gap;
  in.p = p;
  in.Lambda = {Lambda, 0.0};
  in.slip = {slip, 0.0};
  in.stiffnessScale = kStiffness;
  return in;
}

// The force a row stands for: |r| times its weight.
double normalForce(const LawOutput& out) {
  return std::abs(out.r[2] * out.normalRowForce);
}
double frictionForce(const LawOutput& out) {
  return std::abs(out.r[3] * out.frictionRowForce);
}

TEST(ContactRowForce, AStickPointsSlipWeighsAsTheContactStiffnessTimesIt) {
  for (const std::string name : {"lagrange", "augmented-lagrangian"}) {
    const auto law = makeLaw(name);
    LawOutput out;
    // Closed (p = 1, g = -1e-9), stuck (Lambda = 0.1), slipped by 1e-4.
    law->evaluate(point(-1e-9, 1.0, 0.1, 1e-4), out);
    ASSERT_EQ(out.status, ContactStatus::Stick) << name;
    EXPECT_NEAR(frictionForce(out), 0.5 * kStiffness * 1e-4, 1e-9) << name;  // w E/h v
    // (p - p^) / c_n cancels 8 digits: 1e-6 relative.
    EXPECT_NEAR(normalForce(out), 0.5 * kStiffness * 1e-9, 1e-6 * 0.5 * kStiffness * 1e-9) << name;
  }
}

TEST(ContactRowForce, ASlipPointsDirectionErrorWeighsAsItsThreshold) {
  for (const std::string name : {"lagrange", "augmented-lagrangian"}) {
    const auto law = makeLaw(name);
    LawOutput out;
    // Closed, slipping forwards (Lambda + c_t v = 2.5 > 1), Lambda 2 where the direction is 1.
    law->evaluate(point(0.0, 1.0, 2.0, 0.1), out);
    ASSERT_EQ(out.status, ContactStatus::Slip) << name;
    EXPECT_NEAR(frictionForce(out), 0.5 * 0.3 * 1.0 * (2.0 - 1.0), 1e-12) << name;  // w mu p dL
  }
}

TEST(ContactRowForce, AnOpenPointsPressureWeighsAsItself) {
  for (const std::string name : {"lagrange", "augmented-lagrangian"}) {
    const auto law = makeLaw(name);
    LawOutput out;
    // Apart by 1 with a pressure of 0.25 left: open (p - c_n g < 0).
    law->evaluate(point(1.0, 0.25, 0.0, 0.0), out);
    ASSERT_EQ(out.status, ContactStatus::Free) << name;
    EXPECT_NEAR(normalForce(out), 0.5 * 0.25, 1e-12) << name;  // w p
    EXPECT_EQ(frictionForce(out), 0.0) << name;                // open: no friction force
  }
}

TEST(ContactRowForce, LawsWithoutMultipliersHaveNoRowsToWeigh) {
  const Penalty law(100.0, 50.0);
  LawOutput out;
  law.evaluate(point(-1e-3, 0.0, 0.0, 1e-4), out);
  EXPECT_EQ(out.normalRowForce, 0.0);
  EXPECT_EQ(out.frictionRowForce, 0.0);
}

}  // namespace
}  // namespace contactlab
