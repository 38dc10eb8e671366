#include "MeshTestUtils.hpp"

#include "core/mesh/MeshGenerators.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

// Cell and node counts for 3 x 2 divisions.
class RectangleGenerator : public ::testing::TestWithParam<test::GeneratorCase> {};

TEST_P(RectangleGenerator, CountsGroupsAreaAndBoundaries) {
  const auto& tc = GetParam();
  RectangleParams p;
  p.origin = {1.0, -0.5};
  p.lengths = {3.0, 2.0};
  p.divisions = {3, 2};
  p.elementType = tc.type;
  const Mesh mesh = generateRectangle(p);

  test::expectGeneratedBlock(mesh, tc);
  EXPECT_NEAR(test::blockMeasure(mesh, "body"), 6.0, 1e-12);

  const std::vector<std::string> names{"bottom",    "right",     "top",       "left",
                                       "corner-bl", "corner-br", "corner-tr", "corner-tl"};
  EXPECT_EQ(mesh.boundaryNames(), names);
  const int order = info(tc.cellType).order;
  for (const auto& [side, axis, value, n] :
       {std::tuple{"bottom", 1, -0.5, 3}, std::tuple{"top", 1, 1.5, 3},
        std::tuple{"left", 0, 1.0, 2}, std::tuple{"right", 0, 4.0, 2}}) {
    const auto groups = mesh.findBoundaries(side);
    ASSERT_EQ(groups.size(), 1u);
    EXPECT_EQ(groups[0]->type, tc.lineType);
    EXPECT_EQ(groups[0]->size(), static_cast<std::size_t>(n));
    const auto nodes = mesh.boundaryNodes(side);
    EXPECT_EQ(nodes.size(), static_cast<std::size_t>(order * n + 1));
    for (auto k : nodes)
      EXPECT_NEAR(test::node(mesh, k)[axis], value, 1e-12) << side;
  }
  const auto bl = mesh.boundaryNodes("corner-bl");
  ASSERT_EQ(bl.size(), 1u);
  EXPECT_NEAR(test::node(mesh, bl[0])[0], 1.0, 1e-12);
  EXPECT_NEAR(test::node(mesh, bl[0])[1], -0.5, 1e-12);
  const auto tr = mesh.boundaryNodes("corner-tr");
  ASSERT_EQ(tr.size(), 1u);
  EXPECT_NEAR(test::node(mesh, tr[0])[0], 4.0, 1e-12);
  EXPECT_NEAR(test::node(mesh, tr[0])[1], 1.5, 1e-12);
}

// 3 x 2 divisions: 7*5 = 35 grid points at order 2, 4*3 = 12 at order 1.
INSTANTIATE_TEST_SUITE_P(AllTypes, RectangleGenerator,
                         ::testing::ValuesIn(test::generatorCases2D(6, 12, 29, 35)),
                         [](const auto& info) { return info.param.type; });

// Top Shift: a parallelogram of the same area, corners moved, mid-side nodes still halfway.
TEST(RectangleGenerator, TopShiftShearsIntoAParallelogram) {
  RectangleParams p;
  p.origin = {1.0, -0.5};
  p.lengths = {3.0, 2.0};
  p.divisions = {3, 2};
  p.elementType = "quad8";
  p.topShift = 1.5;
  const Mesh mesh = generateRectangle(p);
  EXPECT_NEAR(test::blockMeasure(mesh, "body"), 6.0, 1e-12);
  EXPECT_GT(test::minJacobian(mesh), 0.0);
  const auto tr = mesh.boundaryNodes("corner-tr");
  EXPECT_NEAR(test::node(mesh, tr[0])[0], 5.5, 1e-12);
  const auto bl = mesh.boundaryNodes("corner-bl");
  EXPECT_NEAR(test::node(mesh, bl[0])[0], 1.0, 1e-12);
  for (auto k : mesh.boundaryNodes("left")) {
    const auto x = test::node(mesh, k);
    EXPECT_NEAR(x[0], 1.0 + 1.5 * (x[1] + 0.5) / 2.0, 1e-12);
  }
}

TEST(RectangleGenerator, CornersMapOntoCooksMembrane) {
  RectangleParams p;
  p.divisions = {4, 3};
  p.elementType = "quad9";
  p.corners = std::array<double, 8>{0, 0, 48, 44, 48, 60, 0, 44};
  const Mesh mesh = generateRectangle(p);
  // Trapezoid with parallel sides 44 and 16, 48 apart; straight sides keep quad9's area exact.
  EXPECT_NEAR(test::blockMeasure(mesh, "body"), 48.0 * (44.0 + 16.0) / 2.0, 1e-9);
  EXPECT_GT(test::minJacobian(mesh), 0.0);
  const auto tr = mesh.boundaryNodes("corner-tr");
  EXPECT_NEAR(test::node(mesh, tr[0])[0], 48.0, 1e-12);
  EXPECT_NEAR(test::node(mesh, tr[0])[1], 60.0, 1e-12);
  for (auto k : mesh.boundaryNodes("bottom")) {
    const auto x = test::node(mesh, k);
    EXPECT_NEAR(x[1], 44.0 / 48.0 * x[0], 1e-12);
  }
  p.corners = std::array<double, 8>{0, 0, 0, 44, 48, 60, 48, 44};  // clockwise
  EXPECT_THROW(generateRectangle(p), std::invalid_argument);
}

TEST(RectangleGeneratorErrors, NameTheParameter) {
  RectangleParams p;
  p.elementType = "hex8";
  try {
    generateRectangle(p);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "rectangle generator: element type 'hex8' is not supported; valid choices: "
                 "tri3, tri6, quad4, quad8, quad9");
  }
  p.elementType = "quad4";
  p.divisions = {0, 1};
  EXPECT_THROW(generateRectangle(p), std::invalid_argument);
  p.divisions = {1, 1};
  p.lengths = {1.0, -1.0};
  EXPECT_THROW(generateRectangle(p), std::invalid_argument);
}

}  // namespace
}  // namespace contactlab
