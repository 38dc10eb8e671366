// A closed point whose friction threshold is round-off (touching without pressure) transmits no
// friction: every law says so (LawOutput::frictionlessClosed), so that the results write it as
// closed without friction rather than as stick (the grazing pad slid 0.05 reported stuck).
#include "formulations/AugmentedLagrangian.hpp"
#include "formulations/ContactLaw.hpp"
#include "formulations/Lagrange.hpp"
#include "formulations/Penalty.hpp"

#include <gtest/gtest.h>
#include <memory>
#include <string>

namespace contactlab {
namespace {

std::unique_ptr<ContactLaw> makeLaw(const std::string& name) {
  if (name == "penalty") return std::make_unique<Penalty>(100.0, 50.0);
  if (name == "lagrange") return std::make_unique<Lagrange>(10.0, 5.0);
  return std::make_unique<AugmentedLagrangian>(10.0, 5.0);
}

// A 2D point at zero gap and zero pressure, sliding by `slip`.
LawInput touching(double slip) {
  LawInput in;
  in.weight = 0.5;
  in.mu = 0.3;
  in.nt = 1;
  in.gap = 0.0;
  in.slip = {slip, 0.0};
  return in;
}

TEST(FrictionlessClosed, TouchingWithoutPressureCarriesNoFriction) {
  for (const std::string name : {"penalty", "lagrange", "augmented-lagrangian"}) {
    const auto law = makeLaw(name);
    LawOutput out;
    law->evaluate(touching(0.05), out);
    EXPECT_NE(out.status, ContactStatus::Free) << name;  // touching counts as closed
    EXPECT_TRUE(out.frictionlessClosed) << name;
    EXPECT_EQ(out.tangentialTraction[0], 0.0) << name;
  }
}

TEST(FrictionlessClosed, APressedPointCarriesFriction) {
  for (const std::string name : {"penalty", "lagrange", "augmented-lagrangian"}) {
    const auto law = makeLaw(name);
    LawInput in = touching(0.05);
    in.gap = -1e-3;  // pressed: p^ = c 1e-3 (penalty: eps_n 1e-3)
    in.p = 0.1;
    LawOutput out;
    law->evaluate(in, out);
    EXPECT_NE(out.status, ContactStatus::Free) << name;
    EXPECT_FALSE(out.frictionlessClosed) << name;
  }
}

TEST(FrictionlessClosed, AnOpenPointIsNotClosed) {
  for (const std::string name : {"penalty", "lagrange", "augmented-lagrangian"}) {
    const auto law = makeLaw(name);
    LawInput in = touching(0.05);
    in.gap = 1e-3;
    LawOutput out;
    law->evaluate(in, out);
    EXPECT_EQ(out.status, ContactStatus::Free) << name;
    EXPECT_FALSE(out.frictionlessClosed) << name;
  }
}

}  // namespace
}  // namespace contactlab
