#include "MeshTestUtils.hpp"

#include "core/mesh/MeshGenerators.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

class HalfSphereGenerator : public ::testing::TestWithParam<std::string> {};

TEST_P(HalfSphereGenerator, GroupsVolumeAndBoundaries) {
  HalfSphereParams p;
  p.centre = {1.0, -1.0, 2.0};
  p.radius = 1.0;
  p.grading = {0.15, 0.4, 0.1, 0.5};
  p.elementType = GetParam();
  const Mesh mesh = generateHalfSphere(p);

  EXPECT_EQ(mesh.dim, 3);
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].name, "body");
  EXPECT_EQ(mesh.blocks[0].type, elementTypeFromName(GetParam()));
  EXPECT_GT(test::minJacobian(mesh), 0.0);
  // Straight-sided cells under the sphere: a few percent less than the exact volume.
  const double volume = test::blockMeasure(mesh, "body");
  EXPECT_LT(volume, 2 * M_PI / 3);
  EXPECT_GT(volume, 0.93 * 2 * M_PI / 3);

  for (auto n : mesh.boundaryNodes("flat"))
    EXPECT_NEAR(test::node(mesh, n)[2], 2.0, 1e-9);
  for (auto n : mesh.boundaryNodes("curved")) {
    const auto x = test::node(mesh, n);
    EXPECT_NEAR(
        std::sqrt((x[0] - 1) * (x[0] - 1) + (x[1] + 1) * (x[1] + 1) + (x[2] - 2) * (x[2] - 2)), 1.0,
        1e-6);
    EXPECT_LE(x[2], 2.0 + 1e-9);
  }
  const auto contact = mesh.boundaryNodes("contact-point");
  ASSERT_EQ(contact.size(), 1u);
  const auto c = test::node(mesh, contact[0]);
  EXPECT_NEAR(c[0], 1.0, 1e-12);
  EXPECT_NEAR(c[1], -1.0, 1e-12);
  EXPECT_NEAR(c[2], 1.0, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(AllTypes, HalfSphereGenerator,
                         ::testing::Values("tet4", "tet10", "hex8", "hex20", "hex27"));

TEST(HalfSphereGeneratorErrors, NameTheParameter) {
  HalfSphereParams p;
  p.radius = 0;
  try {
    generateHalfSphere(p);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "half-sphere generator: Radius = 0 must be a positive number");
  }
}

}  // namespace
}  // namespace contactlab
