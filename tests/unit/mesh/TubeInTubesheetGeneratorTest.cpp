// The tube-in-tubesheet generator (issue 18): two disjoint bodies, every node (mid-side nodes
// included) on its cylinder, on a cut's plane or on a z grid plane, the volumes those of the
// sector's annuli, the expansion group exactly the inner face between its planes, no inverted
// cell, and bad parameters refused by name.
#include "MeshTestUtils.hpp"

#include "core/mesh/ElementEstimate.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

TubeInTubesheetParams smallTube(const std::string& type) {
  TubeInTubesheetParams p;
  p.axialDivisions = {1, 3, 1};
  p.sheetAxialDivisions = 4;
  p.sheetRadialDivisions = 3;
  p.elementType = type;
  return p;
}

double radius(const Mesh& mesh, std::int64_t n) {
  const auto x = test::node(mesh, n);
  return std::hypot(x[0], x[1]);
}

class TubeInTubesheet : public ::testing::TestWithParam<std::string> {};

TEST_P(TubeInTubesheet, BodiesCylindersPlanesAndGroups) {
  const auto p = smallTube(GetParam());
  const Mesh mesh = generateTubeInTubesheet(p);
  EXPECT_EQ(mesh.dim, 3);
  EXPECT_EQ(mesh.blockNames(), (std::vector<std::string>{"tube", "tubesheet"}));
  EXPECT_GT(test::minJacobian(mesh), 0.0);
  const double a = p.tubeOuterDiameter / 2 - p.tubeWall, b = p.tubeOuterDiameter / 2;
  const double hole = b + p.clearance, angle = p.angle * M_PI / 180.0;
  // Disjoint bodies.
  const auto tube = test::blockNodes(mesh, "tube"), sheet = test::blockNodes(mesh, "tubesheet");
  for (auto n : tube)
    EXPECT_EQ(sheet.count(n), 0u);
  // Cylinders: every node of the radial faces on its radius.
  for (const auto& [group, r] : {std::pair{"tube-inner", a}, std::pair{"tube-outer", b},
                                 std::pair{"hole", hole}, std::pair{"sheet-outer", 15.0}})
    for (auto n : mesh.boundaryNodes(group))
      EXPECT_NEAR(radius(mesh, n), r, 1e-12 * r) << group;
  // Cuts: y = 0 exactly, and the plane at Angle.
  for (auto n : mesh.boundaryNodes("cut-start"))
    EXPECT_EQ(test::node(mesh, n)[1], 0.0);
  for (auto n : mesh.boundaryNodes("cut-end")) {
    const auto x = test::node(mesh, n);
    EXPECT_NEAR(-std::sin(angle) * x[0] + std::cos(angle) * x[1], 0.0, 1e-12 * hole);
  }
  // The expansion group: the inner face's nodes with z in [start, end], and all of them.
  std::size_t inside = 0;
  for (auto n : mesh.boundaryNodes("tube-inner")) {
    const double z = test::node(mesh, n)[2];
    inside += z >= p.expansionStart - 1e-12 && z <= p.expansionEnd + 1e-12;
  }
  const auto expanded = mesh.boundaryNodes("tube-inner-expanded");
  EXPECT_EQ(expanded.size(), inside);
  for (auto n : expanded) {
    const double z = test::node(mesh, n)[2];
    EXPECT_TRUE(z >= p.expansionStart - 1e-12 && z <= p.expansionEnd + 1e-12);
  }
  // Volumes of the sector annuli (straight-sided cells: the chords' polygon, within 0.5 %).
  const double sector = p.angle / 360.0 * M_PI * p.thickness;
  EXPECT_NEAR(test::blockMeasure(mesh, "tube"), sector * (b * b - a * a),
              5e-3 * sector * (b * b - a * a));
  EXPECT_NEAR(test::blockMeasure(mesh, "tubesheet"), sector * (225.0 - hole * hole),
              5e-3 * sector * (225.0 - hole * hole));
  // The estimate is the cell count.
  std::size_t cells = 0;
  for (const auto& g : mesh.blocks)
    cells += g.size();
  EXPECT_EQ(static_cast<double>(cells), estimateElements(p));
}

INSTANTIATE_TEST_SUITE_P(Hexahedra, TubeInTubesheet, ::testing::Values("hex8", "hex20", "hex27"));

TEST(TubeInTubesheet, RefusesBadParametersByName) {
  auto refused = [](const std::function<void(TubeInTubesheetParams&)>& change,
                    const std::string& words) {
    TubeInTubesheetParams p = smallTube("hex8");
    change(p);
    try {
      generateTubeInTubesheet(p);
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted; expected: " << words;
  };
  refused([](auto& p) { p.tubeWall = 20; }, "Tube Wall");
  refused([](auto& p) { p.sheetOuterRadius = 9; }, "Sheet Outer Radius");
  refused([](auto& p) { p.expansionEnd = 30; }, "expansion zone");
  refused([](auto& p) { p.angle = 120; }, "Angle");
  refused([](auto& p) { p.axialDivisions = {0, 3, 1}; }, "below");
  refused([](auto& p) { p.elementType = "tet4"; }, "tet4");
  refused([](auto& p) { p.clearance = -0.1; }, "Clearance");
}

}  // namespace
}  // namespace contactlab
