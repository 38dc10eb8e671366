// The contact discretization axis: selection by its registry alone. Each entry builds the zone's
// discretization against a master surface or an obstacle; what the pipeline relies on (collocation
// at the slave nodes, a master normal at one point, a multiplier basis) is the type's trait;
// `automatic` picks an integrating type on facets whose corners carry no pressure.
#include "base/InputError.hpp"
#include "core/mesh/MeshGenerators.hpp"
#include "formulations/ContactDiscretizationType.hpp"
#include "formulations/FormulationRegistry.hpp"
#include "formulations/MortarDiscretization.hpp"
#include "formulations/NodeToSegmentDiscretization.hpp"
#include "formulations/ObstacleDiscretization.hpp"
#include "formulations/ObstacleMortarDiscretization.hpp"

#include <gtest/gtest.h>

namespace contactlab {
namespace {

std::shared_ptr<const ContactLaw> law(const std::string& name) {
  registerFormulations();
  Teuchos::ParameterList p = *formulationRegistry().get(name).validParameters();
  if (p.isParameter("Normal Augmentation")) p.set("Normal Augmentation", 1e4);
  if (p.isParameter("Normal Penalty")) p.set("Normal Penalty", 1e4);
  return formulationRegistry().get(name).build(p);
}

Mesh stacked(const std::string& elementType) {
  StackedBlocks3DParams b;
  b.lowerDivisions = {2, 2, 1};
  b.upperDivisions = {2, 2, 1};
  b.elementType = elementType;
  return generateStackedBlocks3D(b);
}

ContactZone zone(const std::string& discretization) {
  ContactZone z;
  z.name = "interface";
  z.slave = "upper-bottom";
  z.master = "lower-top";
  z.discretization = discretization;
  z.law = law("augmented-lagrangian");
  return z;
}

TEST(ContactDiscretizationType, EveryEntryBuildsAgainstASurfaceAndAnObstacle) {
  registerContactDiscretizations();
  const Mesh mesh = stacked("hex8");
  const auto& names = contactDiscretizationRegistry().names();
  ASSERT_EQ(names, (std::vector<std::string>{"node-to-segment", "mortar"}));
  ContactZone surface = zone("node-to-segment");
  EXPECT_NE(
      dynamic_cast<NodeToSegmentDiscretization*>(makeContactDiscretization(surface, mesh, 3).get()),
      nullptr);
  surface.discretization = "mortar";
  EXPECT_NE(dynamic_cast<MortarDiscretization*>(makeContactDiscretization(surface, mesh, 3).get()),
            nullptr);
  ContactZone obstacle = zone("node-to-segment");
  obstacle.master.clear();
  obstacle.obstacle = RigidObstacleSpec{};
  obstacle.obstacle->direction = {0, 0, -1};
  obstacle.obstacle->point = {0, 0, 1.5};
  EXPECT_NE(
      dynamic_cast<ObstacleDiscretization*>(makeContactDiscretization(obstacle, mesh, 3).get()),
      nullptr);
  obstacle.discretization = "mortar";
  EXPECT_NE(dynamic_cast<ObstacleMortarDiscretization*>(
                makeContactDiscretization(obstacle, mesh, 3).get()),
            nullptr);
}

TEST(ContactDiscretizationType, AnUnknownNameIsAnInputErrorNamingTheChoices) {
  ContactZone z = zone("segment-to-segment");
  try {
    makeContactDiscretization(z, stacked("hex8"), 3);
    FAIL() << "accepted an unknown discretization";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("Contact/interface"), std::string::npos) << message;
    EXPECT_NE(message.find("node-to-segment, mortar"), std::string::npos) << message;
  }
}

TEST(ContactDiscretizationType, TraitsAndLabels) {
  const auto& nts = contactDiscretizationType("node-to-segment");
  const auto& mortar = contactDiscretizationType("mortar");
  EXPECT_TRUE(nts.traits().collocatesAtSlaveNodes);
  EXPECT_FALSE(mortar.traits().collocatesAtSlaveNodes);
  ContactZone z = zone("mortar");
  EXPECT_EQ(nts.label(z), "node-to-segment");
  EXPECT_EQ(mortar.label(z), "mortar (dual)");
  z.multiplierBasis = MultiplierBasis::Standard;
  EXPECT_EQ(mortar.label(z), "mortar (standard)");
}

TEST(ContactDiscretizationType, TheNormalFieldIsRefusedWhereNoMasterPointIsPaired) {
  const auto normalField = law("normal-field-augmented-lagrangian");
  EXPECT_EQ(contactDiscretizationType("node-to-segment").refusal(*normalField), "");
  const std::string refusal = contactDiscretizationType("mortar").refusal(*normalField);
  EXPECT_NE(refusal.find("use node-to-segment"), std::string::npos) << refusal;
  EXPECT_EQ(contactDiscretizationType("mortar").refusal(*law("augmented-lagrangian")), "");
}

TEST(ContactDiscretizationType, AutomaticIntegratesOnlyOnCornerlessFacets) {
  const auto al = law("augmented-lagrangian");
  for (const char* type : {"hex8", "tet4", "hex27"}) {
    const AutomaticDiscretization pick =
        chooseAutomaticDiscretization(stacked(type), "upper-bottom", *al);
    EXPECT_EQ(pick.name, "node-to-segment") << type;
    EXPECT_EQ(pick.reason, "") << type;
  }
  for (const char* type : {"hex20", "tet10"}) {
    const AutomaticDiscretization pick =
        chooseAutomaticDiscretization(stacked(type), "upper-bottom", *al);
    EXPECT_EQ(pick.name, "mortar") << type;
    EXPECT_NE(pick.reason.find("slave facets"), std::string::npos) << type;
  }
  // The normal field has no integrating type: the default, whose advice the scene reader gives.
  EXPECT_EQ(chooseAutomaticDiscretization(stacked("hex20"), "upper-bottom",
                                          *law("normal-field-augmented-lagrangian"))
                .name,
            "node-to-segment");
}

}  // namespace
}  // namespace contactlab
