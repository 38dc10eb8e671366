// The element-technology axis: each registered technology's refusals (which cells, kinematics
// and geometries it cannot form, with a sentence), the automatic choice per material and cell,
// and a Problem resolving its blocks and reporting the tangent's symmetry.
#include "base/InputError.hpp"
#include "core/materials/J2SmallStrain.hpp"
#include "core/materials/LinearElastic.hpp"
#include "core/materials/NeoHookean.hpp"
#include "core/materials/SimoMiehe.hpp"
#include "core/problem/ElementTechnology.hpp"

#include <gtest/gtest.h>

namespace contactlab {
namespace {

ElementSetting setting(ElementType type, Kinematics kinematics, bool axisymmetric = false,
                       bool planeStress = false) {
  ElementSetting s;
  s.type = type;
  s.kinematics = kinematics;
  s.axisymmetric = axisymmetric;
  s.planeStress = planeStress;
  return s;
}

std::shared_ptr<ElementTechnology> technology(const std::string& name) {
  registerElementTechnologies();
  return elementTechnologyRegistry().get(name).build(Teuchos::ParameterList());
}

LinearElastic elastic(double nu) {
  return LinearElastic(200.0, nu);
}

J2SmallStrain j2() {
  J2SmallStrain::Parameters p;
  p.youngModulus = TemperatureDependent(200.0);
  p.yieldStress = TemperatureDependent(1.0);
  return J2SmallStrain(p);
}

SimoMiehe simoMiehe() {
  SimoMiehe::Parameters p;
  p.youngModulus = 200.0;
  p.yieldStress = 1.0;
  return SimoMiehe(p);
}

TEST(ElementTechnology, RegistryHoldsTheFourTechnologies) {
  registerElementTechnologies();
  EXPECT_EQ(elementTechnologyRegistry().joinedNames(), "full, b-bar, f-bar, mixed-up");
}

TEST(ElementTechnology, EachRefusesWhatItCannotForm) {
  const auto S = Kinematics::SmallStrain, F = Kinematics::FiniteStrain;
  using T = ElementType;
  // Accepted.
  for (T t : {T::Tri3, T::Quad4, T::Quad8, T::Tet4, T::Hex27})
    EXPECT_EQ(technology("full")->refusal(setting(t, F)), "");
  EXPECT_EQ(technology("b-bar")->refusal(setting(T::Quad4, S, true)), "");
  EXPECT_EQ(technology("b-bar")->refusal(setting(T::Hex8, S)), "");
  EXPECT_EQ(technology("f-bar")->refusal(setting(T::Hex8, F)), "");
  for (T t : {T::Quad4, T::Quad8, T::Quad9, T::Tri6, T::Tet10, T::Hex8, T::Hex20, T::Hex27})
    for (Kinematics k : {S, F})
      EXPECT_EQ(technology("mixed-up")->refusal(setting(t, k)), "") << info(t).name;
  // Refused, each with its reason.
  EXPECT_NE(technology("b-bar")->refusal(setting(T::Quad4, F)).find("finite-strain"),
            std::string::npos);
  EXPECT_NE(technology("b-bar")->refusal(setting(T::Quad8, S)).find("mixed-up"), std::string::npos);
  EXPECT_NE(technology("f-bar")->refusal(setting(T::Hex8, S)).find("small-strain"),
            std::string::npos);
  EXPECT_NE(technology("f-bar")->refusal(setting(T::Hex27, F)).find("hex27"), std::string::npos);
  EXPECT_NE(technology("mixed-up")->refusal(setting(T::Tet4, S)).find("tet4"), std::string::npos);
  for (const char* name : {"b-bar", "mixed-up"})
    EXPECT_NE(technology(name)->refusal(setting(T::Quad4, S, false, true)).find("plane stress"),
              std::string::npos);
  EXPECT_THROW(technology("f-bar")->kernel(setting(T::Quad8, F)), std::invalid_argument);
}

TEST(ElementTechnology, OnlyFBarLosesSymmetry) {
  EXPECT_TRUE(technology("full")->keepsSymmetry());
  EXPECT_TRUE(technology("b-bar")->keepsSymmetry());
  EXPECT_FALSE(technology("f-bar")->keepsSymmetry());
  EXPECT_TRUE(technology("mixed-up")->keepsSymmetry());
}

TEST(ElementTechnology, AutomaticPicksLockingFreeWhereTheVolumeCannotChange) {
  const auto S = Kinematics::SmallStrain, F = Kinematics::FiniteStrain;
  using T = ElementType;
  EXPECT_EQ(chooseAutomatic(elastic(0.3), setting(T::Quad4, S)).technology, "full");
  EXPECT_EQ(chooseAutomatic(elastic(0.449), setting(T::Hex8, S)).technology, "full");
  EXPECT_EQ(chooseAutomatic(elastic(0.45), setting(T::Hex8, S)).technology, "b-bar");
  EXPECT_EQ(chooseAutomatic(j2(), setting(T::Quad4, S, true)).technology, "b-bar");
  EXPECT_EQ(chooseAutomatic(j2(), setting(T::Quad8, S)).technology, "mixed-up");
  EXPECT_EQ(chooseAutomatic(simoMiehe(), setting(T::Hex8, F)).technology, "mixed-up");
  EXPECT_EQ(chooseAutomatic(simoMiehe(), setting(T::Hex27, F)).technology, "mixed-up");
  EXPECT_EQ(
      chooseAutomatic(NeoHookean::fromYoungPoisson(1.0, 0.48), setting(T::Quad4, F)).technology,
      "mixed-up");
  // Where no technology helps, or none is needed.
  const auto simplex = chooseAutomatic(j2(), setting(T::Tet4, S));
  EXPECT_EQ(simplex.technology, "full");
  EXPECT_NE(simplex.reason.find("tet4"), std::string::npos);
  EXPECT_EQ(chooseAutomatic(j2(), setting(T::Quad4, S, false, true)).technology, "full");
  EXPECT_NE(chooseAutomatic(j2(), setting(T::Quad4, S)).reason.find("constant volume"),
            std::string::npos);
}

TEST(ElementTechnology, ABlockIsRefusedWithTheKeyAndTheValidChoices) {
  const auto law = j2();
  const auto resolved = resolveBlockTechnology(
      "slab", "automatic", law, setting(ElementType::Quad4, Kinematics::SmallStrain));
  EXPECT_EQ(resolved.name, "b-bar");
  EXPECT_FALSE(resolved.reason.empty());
  try {
    resolveBlockTechnology("slab", "f-bar", law,
                           setting(ElementType::Quad4, Kinematics::SmallStrain));
    FAIL() << "f-bar on a small-strain block was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("Materials/slab/Element Technology"), std::string::npos) << what;
    EXPECT_NE(what.find("valid here: automatic, full, b-bar, mixed-up"), std::string::npos) << what;
  }
  EXPECT_THROW(resolveBlockTechnology("slab", "selective", law,
                                      setting(ElementType::Quad4, Kinematics::SmallStrain)),
               InputError);
}

}  // namespace
}  // namespace contactlab
