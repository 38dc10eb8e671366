// The normal-field augmented Lagrangian's law: its declared unknowns, its kappa_n (automatic:
// r_n times the point's size), its refusals, and its pointwise law, which is the augmented
// Lagrangian's (the normal field lives in the kernel: ContactProblemTest checks its tangent).
#include "formulations/AugmentedLagrangian.hpp"
#include "formulations/FormulationRegistry.hpp"
#include "formulations/NormalFieldAugmentedLagrangian.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace contactlab {
namespace {

TEST(NormalFieldLaw, DeclaresItsSlaveNormalBesideTheMultipliers) {
  const NormalFieldAugmentedLagrangian law(100.0, 10.0, 0.0);
  EXPECT_TRUE(law.hasNormalField());
  EXPECT_EQ(law.pointUnknowns(0, 2), 3);  // p, n_s
  EXPECT_EQ(law.pointUnknowns(1, 2), 4);  // p, Lambda, n_s
  EXPECT_EQ(law.pointUnknowns(2, 3), 6);
  EXPECT_EQ(law.size(2), 6);  // the law's own variables stay (g, v, p, Lambda)
  EXPECT_FALSE(law.symmetricJacobian(0));
  const AugmentedLagrangian plain(100.0, 10.0);
  EXPECT_FALSE(plain.hasNormalField());
  EXPECT_EQ(plain.pointUnknowns(2, 3), 3);
}

TEST(NormalFieldLaw, KappaIsGivenOrRnTimesThePointSize) {
  EXPECT_DOUBLE_EQ(NormalFieldAugmentedLagrangian(100.0, 10.0, 0.0).normalFieldPenalty(0.02), 2.0);
  EXPECT_DOUBLE_EQ(NormalFieldAugmentedLagrangian(100.0, 10.0, 7.0).normalFieldPenalty(0.02), 7.0);
  EXPECT_THROW(NormalFieldAugmentedLagrangian(100.0, 10.0, -1.0), std::invalid_argument);
  registerFormulations();
  Teuchos::ParameterList p =
      *formulationRegistry().get("normal-field-augmented-lagrangian").validParameters();
  p.set("Normal Augmentation", 100.0);
  p.set("Normal Field Penalty", -1.0);
  try {
    formulationRegistry().get("normal-field-augmented-lagrangian").build(p);
    FAIL() << "a negative kappa_n was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("Normal Field Penalty"), std::string::npos) << e.what();
  }
}

TEST(NormalFieldLaw, ItsPointwiseLawIsTheAugmentedLagrangians) {
  const NormalFieldAugmentedLagrangian field(100.0, 10.0, 3.0);
  const AugmentedLagrangian plain(100.0, 10.0);
  LawInput in;
  in.weight = 0.1;
  in.mu = 0.3;
  in.nt = 2;
  in.gap = -1e-3;
  in.slip = {2e-3, -1e-3};
  in.p = 0.05;
  in.Lambda = {0.4, 0.7};
  LawOutput a, b;
  field.evaluate(in, a);
  plain.evaluate(in, b);
  EXPECT_EQ(a.r, b.r);
  EXPECT_EQ(a.J, b.J);
  EXPECT_EQ(a.status, b.status);
}

}  // namespace
}  // namespace contactlab
