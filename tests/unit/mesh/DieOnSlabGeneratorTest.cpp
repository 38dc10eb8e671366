// The die-on-slab generator (Puso & Laursen's 3D ironing): two disjoint bodies, the die bent
// onto its cylindrical shell segment with every node (mid-side nodes included) on the arcs
// and rays, no inverted cell, and bad parameters refused by name.
#include "MeshTestUtils.hpp"

#include "core/mesh/ElementEstimate.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <cmath>
#include <functional>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

DieOnSlabParams smallDie(const std::string& type) {
  DieOnSlabParams p;
  p.slabDivisions = {6, 2, 2};
  p.dieDivisions = {1, 2, 8};
  p.gap = 0.1;
  p.elementType = type;
  return p;
}

// Distance of node n from the die's axis (the line x = Die Start, z = top + gap + R).
double radius(const Mesh& mesh, const DieOnSlabParams& p, std::int64_t n) {
  const auto x = test::node(mesh, n);
  const double cz = p.slabLengths[2] + p.gap + p.dieRadius;
  return std::hypot(x[0] - p.dieStart, x[2] - cz);
}

class DieOnSlab : public ::testing::TestWithParam<std::string> {};

TEST_P(DieOnSlab, SlabAndDieGeometry) {
  const auto p = smallDie(GetParam());
  const Mesh mesh = generateDieOnSlab(p);
  EXPECT_EQ(mesh.dim, 3);
  EXPECT_EQ(mesh.blockNames(), (std::vector<std::string>{"slab", "die"}));
  EXPECT_EQ(
      mesh.boundaryNames(),
      (std::vector<std::string>{"slab-xmin", "slab-xmax", "slab-ymin", "slab-ymax", "slab-bottom",
                                "slab-top", "die-inner", "die-outer", "die-sides", "die-ends"}));
  EXPECT_GT(test::minJacobian(mesh), 0.0);
  EXPECT_EQ(double(mesh.numElements()), estimateElements(p));
  const auto slab = test::blockNodes(mesh, "slab"), die = test::blockNodes(mesh, "die");
  EXPECT_EQ(slab.size() + die.size(), mesh.numNodes());  // disjoint, all used
  EXPECT_NEAR(test::blockMeasure(mesh, "slab"), 9.0 * 4.0 * 3.0, 1e-10);
  // The shell segment's volume; straight-sided cells (the measure uses the corner map) cut
  // each 22.5-degree arc by its chord: area factor sin(a)/a = 0.974 at the mean radius.
  const double ro = p.dieRadius, ri = ro - p.dieThickness;
  const double shell = 0.5 * M_PI * (ro * ro - ri * ri) * p.dieWidth;
  const double a = M_PI / 8;
  EXPECT_NEAR(test::blockMeasure(mesh, "die"), shell * std::sin(a) / a, 1e-3 * shell);
  for (auto n : mesh.boundaryNodes("die-outer"))
    EXPECT_NEAR(radius(mesh, p, n), ro, 1e-12);
  for (auto n : mesh.boundaryNodes("die-inner"))
    EXPECT_NEAR(radius(mesh, p, n), ri, 1e-12);
  // Lowest point: Gap above the slab, at Die Start; the half cylinder's ends at the axis.
  double lowest = 1e9, highest = -1e9;
  for (auto n : mesh.boundaryNodes("die-outer")) {
    lowest = std::min(lowest, test::node(mesh, n)[2]);
    highest = std::max(highest, test::node(mesh, n)[2]);
  }
  EXPECT_NEAR(lowest, 3.1, 1e-12);
  EXPECT_NEAR(highest, 3.1 + ro, 1e-12);
  for (auto n : mesh.boundaryNodes("die-sides")) {
    const double y = test::node(mesh, n)[1];
    EXPECT_TRUE(std::abs(y + 0.6) < 1e-12 || std::abs(y - 4.6) < 1e-12) << y;
  }
  test::expectCoordinate(mesh, "slab-top", 2, 3.0);
}

INSTANTIATE_TEST_SUITE_P(AllTypes, DieOnSlab,
                         ::testing::Values("tet4", "tet10", "hex8", "hex20", "hex27"));

TEST(DieOnSlabGenerator, MidSideNodesLieOnTheArcs) {
  // hex27's through-thickness mid nodes sit on the mean radius, at the arc's angular midpoints.
  auto p = smallDie("hex27");
  const Mesh mesh = generateDieOnSlab(p);
  const double mid = p.dieRadius - p.dieThickness / 2;
  std::size_t onMean = 0;
  for (auto n : test::blockNodes(mesh, "die"))
    onMean += std::abs(radius(mesh, p, n) - mid) < 1e-12;
  EXPECT_EQ(onMean, (2 * 2 + 1) * (2 * 8 + 1));  // width x arc grid at order 2
}

TEST(DieOnSlabGenerator, RefusesBadParametersByName) {
  const std::vector<std::pair<std::string, std::function<void(DieOnSlabParams&)>>> cases{
      {"Die Thickness", [](DieOnSlabParams& p) { p.dieThickness = 3.0; }},
      {"Die Angle", [](DieOnSlabParams& p) { p.dieAngle = 200; }},
      {"Die Divisions[2]", [](DieOnSlabParams& p) { p.dieDivisions[2] = 5; }},
      {"Die Start", [](DieOnSlabParams& p) { p.dieStart = 10; }},
      {"Slab Width", [](DieOnSlabParams& p) { p.slabLengths[1] = 0; }},
      {"quad4", [](DieOnSlabParams& p) { p.elementType = "quad4"; }}};
  for (const auto& [key, spoil] : cases) {
    auto p = smallDie("hex8");
    spoil(p);
    try {
      generateDieOnSlab(p);
      ADD_FAILURE() << key << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace contactlab
