#include "MeshTestUtils.hpp"

#include "core/mesh/MeshGenerators.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

class HalfDiscGenerator : public ::testing::TestWithParam<std::string> {};

TEST_P(HalfDiscGenerator, GroupsAreaBoundariesAndGrading) {
  HalfDiscParams p;
  p.centre = {0.5, 2.0};
  p.radius = 1.5;
  p.grading = {0.03, 0.3, 0.05, 0.5};
  p.elementType = GetParam();
  const Mesh mesh = generateHalfDisc(p);
  const auto type = elementTypeFromName(GetParam());

  EXPECT_EQ(mesh.dim, 2);
  EXPECT_EQ(mesh.blockNames(), std::vector<std::string>{"body"});
  ASSERT_EQ(mesh.blocks.size(), 1u);  // all-quad or all-tri, never mixed
  EXPECT_EQ(mesh.blocks[0].type, type);
  EXPECT_GT(test::minJacobian(mesh), 0.0);
  // Corner-based area misses the circular segments under the arc's chords: O(h^2).
  const double area = test::blockMeasure(mesh, "body"), exact = M_PI * 1.5 * 1.5 / 2;
  EXPECT_LT(area, exact);
  EXPECT_GT(area, 0.99 * exact);

  test::expectCoordinate(mesh, "flat", 1, 2.0);
  std::vector<double> arcDistances;  // distance of arc nodes to the contact point
  for (auto n : mesh.boundaryNodes("curved")) {
    const auto x = test::node(mesh, n);
    EXPECT_NEAR(std::hypot(x[0] - 0.5, x[1] - 2.0), 1.5, 1e-9);
    EXPECT_LE(x[1], 2.0 + 1e-12);
    arcDistances.push_back(std::hypot(x[0] - 0.5, x[1] - 0.5));
  }
  const auto contact = mesh.boundaryNodes("contact-point");
  ASSERT_EQ(contact.size(), 1u);
  EXPECT_NEAR(test::node(mesh, contact[0])[0], 0.5, 1e-12);
  EXPECT_NEAR(test::node(mesh, contact[0])[1], 0.5, 1e-12);

  // Graded: the arc nodes next to the contact point are about sizeContact (/order) away,
  // while the flat side (far away) has few nodes.
  std::sort(arcDistances.begin(), arcDistances.end());
  ASSERT_GT(arcDistances.size(), 3u);
  EXPECT_EQ(arcDistances[0], 0.0);
  EXPECT_LT(arcDistances[1], 0.06);
  EXPECT_LT(mesh.boundaryNodes("flat").size(), static_cast<std::size_t>(3 * 2 / 0.3 * 2 + 3));
}

INSTANTIATE_TEST_SUITE_P(AllTypes, HalfDiscGenerator,
                         ::testing::Values("tri3", "tri6", "quad4", "quad8", "quad9"));

TEST(HalfDiscGeneratorErrors, NameTheParameter) {
  HalfDiscParams p;
  p.grading.sizeFar = 0.01;
  try {
    generateHalfDisc(p);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("Size Far"), std::string::npos);
  }
  p = HalfDiscParams{};
  p.elementType = "tet4";
  EXPECT_THROW(generateHalfDisc(p), std::invalid_argument);
}

}  // namespace
}  // namespace contactlab

namespace contactlab {
namespace {

// Roller on a base: two bodies, separately meshed (no shared node, not even at the contact
// point), valid elements, each area right, the boundary groups on their curves.
class RollerOnBaseGenerator
    : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(RollerOnBaseGenerator, TwoBodiesTouchingAtOnePoint) {
  RollerOnBaseParams p;
  p.contact = {1.0, 2.0};
  p.radius = 1.0;
  p.base = std::get<0>(GetParam());
  p.baseWidth = 3.0;
  p.baseHeight = 1.5;
  p.grading = {0.03, 0.3, 0.05, 0.5};
  p.elementType = std::get<1>(GetParam());
  const Mesh mesh = generateRollerOnBase(p);
  EXPECT_GT(test::minJacobian(mesh), 0.0);
  const auto roller = test::blockNodes(mesh, "roller"), base = test::blockNodes(mesh, "base");
  for (auto n : roller)
    EXPECT_EQ(base.count(n), 0u) << "node " << n << " is shared by the two bodies";
  const double half = M_PI / 2;
  EXPECT_NEAR(test::blockMeasure(mesh, "roller"), half, 0.01 * half);
  EXPECT_NEAR(test::blockMeasure(mesh, "base"), p.base == "disc" ? half : 4.5,
              0.01 * (p.base == "disc" ? half : 4.5));
  int atContact = 0;
  for (const char* group : {"roller-curved", "base-top"})
    for (auto n : mesh.boundaryNodes(group)) {
      const auto x = test::node(mesh, n);
      if (std::hypot(x[0] - 1.0, x[1] - 2.0) < 1e-12) ++atContact;
      const bool onRoller = std::string(group) == "roller-curved";
      EXPECT_TRUE(onRoller ? x[1] >= 2.0 - 1e-12 : x[1] <= 2.0 + 1e-12) << group;
    }
  EXPECT_EQ(atContact, 2) << "one node of each body at the contact point";
  test::expectCoordinate(mesh, "roller-flat", 1, 3.0);
  for (auto n : mesh.boundaryNodes("base-bottom"))
    EXPECT_NEAR(test::node(mesh, n)[1], p.base == "disc" ? 1.0 : 0.5, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(BasesAndTypes, RollerOnBaseGenerator,
                         ::testing::Combine(::testing::Values("block", "disc"),
                                            ::testing::Values("tri3", "quad4", "quad8")));

TEST(RollerOnBaseGeneratorErrors, NameTheParameter) {
  RollerOnBaseParams p;
  p.base = "cone";
  EXPECT_THROW(generateRollerOnBase(p), std::invalid_argument);
}

}  // namespace
}  // namespace contactlab
