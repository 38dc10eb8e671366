#include "MeshTestUtils.hpp"

#include "core/mesh/MeshGenerators.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

// Number of nodes of `a` with no node of `b` at the same place.
std::size_t unmatched(const Mesh& mesh, const std::vector<std::int64_t>& a,
                      const std::vector<std::int64_t>& b, int axes) {
  std::size_t n = 0;
  for (auto i : a) {
    const auto x = test::node(mesh, i);
    n += std::none_of(b.begin(), b.end(), [&](std::int64_t j) {
      const auto y = test::node(mesh, j);
      double d = 0;
      for (int k = 0; k < axes; ++k)
        d += std::abs(x[k] - y[k]);
      return d < 1e-9;
    });
  }
  return n;
}

class StackedBlocks2D : public ::testing::TestWithParam<std::string> {};

TEST_P(StackedBlocks2D, PatchTestGeometry) {
  StackedBlocks2DParams p;  // V3 2D: total height 2
  p.elementType = GetParam();
  const Mesh mesh = generateStackedBlocks2D(p);
  EXPECT_EQ(mesh.dim, 2);
  EXPECT_EQ(mesh.blockNames(), (std::vector<std::string>{"lower", "upper"}));
  const std::vector<std::string> sides{"lower-bottom", "lower-right", "lower-top", "lower-left",
                                       "upper-bottom", "upper-right", "upper-top", "upper-left"};
  EXPECT_EQ(mesh.boundaryNames(), sides);
  EXPECT_NEAR(test::blockMeasure(mesh, "lower"), 1.0, 1e-12);
  EXPECT_NEAR(test::blockMeasure(mesh, "upper"), 1.0, 1e-12);
  EXPECT_GT(test::minJacobian(mesh), 0.0);
  const bool tri = GetParam().rfind("tri", 0) == 0;
  EXPECT_EQ(test::cellCount(mesh.findBlocks("lower")), tri ? 8u : 4u);
  EXPECT_EQ(test::cellCount(mesh.findBlocks("upper")), tri ? 18u : 9u);

  const auto lower = test::blockNodes(mesh, "lower"), upper = test::blockNodes(mesh, "upper");
  EXPECT_EQ(lower.size() + upper.size(), mesh.numNodes());  // disjoint, all used
  test::expectCoordinate(mesh, "lower-top", 1, 1.0);
  test::expectCoordinate(mesh, "upper-bottom", 1, 1.0);
  test::expectCoordinate(mesh, "upper-top", 1, 2.0);
  // 2 vs 3 divisions: the end points coincide, and at order 2 also x = 0.5.
  const auto lt = mesh.boundaryNodes("lower-top"), ub = mesh.boundaryNodes("upper-bottom");
  EXPECT_EQ(unmatched(mesh, lt, ub, 2), info(elementTypeFromName(GetParam())).order == 1 ? 1u : 2u);
}

INSTANTIATE_TEST_SUITE_P(AllTypes, StackedBlocks2D,
                         ::testing::Values("tri3", "tri6", "quad4", "quad8", "quad9"));

TEST(StackedBlocks2DGenerator, GapAndRotation) {
  StackedBlocks2DParams p;
  p.origin = {1.0, 1.0};
  p.width = 2.0;
  p.lowerHeight = 0.5;
  p.upperHeight = 1.0;
  p.gap = 0.25;
  p.upperRotationDeg = 5.0;
  const Mesh mesh = generateStackedBlocks2D(p);
  test::expectCoordinate(mesh, "lower-top", 1, 1.5);
  EXPECT_NEAR(test::blockMeasure(mesh, "upper"), 2.0, 1e-12);
  // Upper block turned about its centre (2, 2.25): its bottom corners moved off y = 1.75.
  double ymin = 1e9, ymax = -1e9;
  for (auto n : mesh.boundaryNodes("upper-bottom")) {
    ymin = std::min(ymin, test::node(mesh, n)[1]);
    ymax = std::max(ymax, test::node(mesh, n)[1]);
  }
  const double a = 5 * M_PI / 180;
  EXPECT_NEAR(ymin, 2.25 - std::sin(a) - 0.5 * std::cos(a), 1e-12);
  EXPECT_NEAR(ymax, 2.25 + std::sin(a) - 0.5 * std::cos(a), 1e-12);
}

class StackedBlocks3D : public ::testing::TestWithParam<std::string> {};

TEST_P(StackedBlocks3D, PatchTestGeometry) {
  StackedBlocks3DParams p;  // V3 3D: [0,1]^2 x [0,1.05] and [0,1]^2 x [0.95,2]
  p.lowerHeight = 1.05;
  p.upperHeight = 1.05;
  p.gap = -0.1;
  p.lowerDivisions = {2, 2, 1};
  p.upperDivisions = {3, 3, 1};
  p.elementType = GetParam();
  const Mesh mesh = generateStackedBlocks3D(p);
  EXPECT_EQ(mesh.dim, 3);
  EXPECT_EQ(mesh.blockNames(), (std::vector<std::string>{"lower", "upper"}));
  const std::vector<std::string> faces{"lower-xmin",   "lower-xmax", "lower-ymin",   "lower-ymax",
                                       "lower-bottom", "lower-top",  "upper-xmin",   "upper-xmax",
                                       "upper-ymin",   "upper-ymax", "upper-bottom", "upper-top"};
  EXPECT_EQ(mesh.boundaryNames(), faces);
  EXPECT_NEAR(test::blockMeasure(mesh, "lower"), 1.05, 1e-12);
  EXPECT_NEAR(test::blockMeasure(mesh, "upper"), 1.05, 1e-12);
  EXPECT_GT(test::minJacobian(mesh), 0.0);
  const std::size_t perHex = GetParam().rfind("tet", 0) == 0 ? 6 : 1;
  EXPECT_EQ(test::cellCount(mesh.findBlocks("lower")), 4 * perHex);
  EXPECT_EQ(test::cellCount(mesh.findBlocks("upper")), 9 * perHex);

  const auto lower = test::blockNodes(mesh, "lower"), upper = test::blockNodes(mesh, "upper");
  EXPECT_EQ(lower.size() + upper.size(), mesh.numNodes());
  test::expectCoordinate(mesh, "lower-top", 2, 1.05);
  test::expectCoordinate(mesh, "upper-bottom", 2, 0.95);
  test::expectCoordinate(mesh, "upper-top", 2, 2.0);
  test::expectCoordinate(mesh, "upper-xmax", 0, 1.0);
  const auto lt = mesh.boundaryNodes("lower-top"), ub = mesh.boundaryNodes("upper-bottom");
  EXPECT_GT(unmatched(mesh, lt, ub, 2), lt.size() / 2);
}

INSTANTIATE_TEST_SUITE_P(AllTypes, StackedBlocks3D,
                         ::testing::Values("tet4", "tet10", "hex8", "hex20", "hex27"));

TEST(StackedBlocks3DGenerator, RotatedUpperBlock) {
  StackedBlocks3DParams p;
  p.upperRotationDeg = 3.0;
  p.lowerDivisions = {1, 1, 1};
  p.upperDivisions = {2, 2, 1};
  const Mesh mesh = generateStackedBlocks3D(p);
  EXPECT_NEAR(test::blockMeasure(mesh, "upper"), 1.0, 1e-12);
  EXPECT_GT(test::minJacobian(mesh), 0.0);
  // Lower block untouched, upper corners turned about (0.5, 0.5).
  test::expectCoordinate(mesh, "lower-xmin", 0, 0.0);
  const double a = 3 * M_PI / 180;
  bool found = false;
  for (auto n : mesh.boundaryNodes("upper-top")) {
    const auto x = test::node(mesh, n);
    if (std::abs(x[0] - (0.5 + 0.5 * std::cos(a) - 0.5 * std::sin(a))) < 1e-12 &&
        std::abs(x[1] - (0.5 + 0.5 * std::sin(a) + 0.5 * std::cos(a))) < 1e-12)
      found = true;
  }
  EXPECT_TRUE(found) << "corner (1, 1) of the upper block rotated by 3 degrees";
}

TEST(StackedBlocksGeneratorErrors, NameTheParameter) {
  StackedBlocks3DParams p;
  p.gap = -1.0;
  try {
    generateStackedBlocks3D(p);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("gap"), std::string::npos);
  }
  StackedBlocks2DParams q;
  q.upperDivisions = {1, -2};
  EXPECT_THROW(generateStackedBlocks2D(q), std::invalid_argument);
}

}  // namespace
}  // namespace contactlab
