// The normal-field augmented Lagrangian's law: its declared unknowns (and every formulation's
// names for its unknowns), its kappa_n (automatic:
// r_n times the point's size), its refusals, and its pointwise law, which is the augmented
// Lagrangian's (the normal field lives in the kernel: ContactProblemTest checks its tangent).
#include "formulations/AugmentedLagrangian.hpp"
#include "formulations/FormulationRegistry.hpp"
#include "formulations/NormalFieldAugmentedLagrangian.hpp"

#include <algorithm>
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

// Every registered formulation names each unknown it declares, once, for the outputs.
TEST(PointUnknowns, EveryFormulationNamesEachOfItsUnknowns) {
  registerFormulations();
  for (const std::string& type : formulationRegistry().names()) {
    Teuchos::ParameterList p = *formulationRegistry().get(type).validParameters();
    for (const char* required :
         {"Normal Augmentation", "Normal Penalty", "Normal Complementarity Constant"})
      if (p.isParameter(required)) p.set(required, 100.0);
    const auto law = formulationRegistry().get(type).build(p);
    for (int dim : {2, 3})
      for (int nt = 0; nt < dim; ++nt) {
        auto names = law->pointUnknownNames(nt, dim);
        EXPECT_EQ(static_cast<int>(names.size()), law->pointUnknowns(nt, dim)) << type;
        std::sort(names.begin(), names.end());
        EXPECT_EQ(std::unique(names.begin(), names.end()), names.end()) << type;
      }
  }
  const NormalFieldAugmentedLagrangian field(100.0, 10.0, 0.0);
  EXPECT_EQ(
      field.pointUnknownNames(2, 3),
      (std::vector<std::string>{"p", "lambda_1", "lambda_2", "normal_x", "normal_y", "normal_z"}));
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
