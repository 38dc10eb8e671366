#include "MeshTestUtils.hpp"

#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/QuadratureRule.hpp"
#include "core/fem/ReferenceElement.hpp"
#include "core/mesh/ElementEstimate.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <cmath>
#include <functional>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

// Area of the block through the isoparametric map (mid-side nodes included), by a rule exact
// for the map's polynomial degree.
double isoparametricArea(const Mesh& mesh) {
  double area = 0;
  for (const auto& g : mesh.blocks) {
    const auto& ref = ReferenceElement::get(g.type);
    const auto& rule = quadratureRule(g.type, 6);
    const int nn = g.nodesPerCell();
    std::vector<double> x(3 * nn), N(nn), dN(2 * nn), J(4);
    for (std::size_t c = 0; c < g.size(); ++c) {
      for (int a = 0; a < nn; ++a)
        for (int i = 0; i < 3; ++i)
          x[3 * a + i] = mesh.coords[3 * g.nodes[c * nn + a] + i];
      for (int q = 0; q < rule.size(); ++q) {
        ref.shapeDerivatives(&rule.points[2 * q], dN.data());
        jacobian(2, nn, x.data(), dN.data(), J.data());
        area += rule.weights[q] * (J[0] * J[3] - J[1] * J[2]);
      }
    }
  }
  return area;
}

// Areas of nt cells of angle dtheta between radii a and b: straight-sided (the inscribed
// polygon: half the sine of the angle times b^2 - a^2 per cell) and with each arc replaced by the
// parabola through its ends and middle, which is what a line3 edge is (the segment between
// chord and parabola is 2/3 chord x sagitta).
double polygonArea(int nt, double dtheta, double a, double b) {
  return nt * std::sin(dtheta) / 2 * (b * b - a * a);
}
double parabolicArea(int nt, double dtheta, double a, double b) {
  const double half = dtheta / 2;
  return polygonArea(nt, dtheta, a, b) +
         nt * 4.0 / 3 * std::sin(half) * (1 - std::cos(half)) * (b * b - a * a);
}

double radius(const std::array<double, 3>& x, double cx = 0, double cy = 0) {
  return std::hypot(x[0] - cx, x[1] - cy);
}

double degrees(const std::array<double, 3>& x, double cx = 0, double cy = 0) {
  const double d = std::atan2(x[1] - cy, x[0] - cx) * 180 / M_PI;
  return d < -1e-9 ? d + 360 : d;
}

// True when `value` is within 1e-12 (relative to `scale`) of one of `grid`.
bool onGrid(double value, const std::vector<double>& grid, double scale) {
  for (double g : grid)
    if (std::abs(value - g) <= 1e-12 * scale) return true;
  return false;
}

// Cell and node counts for 3 x 4 divisions.
class RingSectorGenerator : public ::testing::TestWithParam<test::GeneratorCase> {};

// A = 1.5 .. 4, 120 degrees about (1, -2), 3 x 4 divisions graded 2:1 towards the inside.
TEST_P(RingSectorGenerator, CountsRadiiArcsAreaAndGroups) {
  const auto& tc = GetParam();
  RingSectorParams p;
  p.centre = {1.0, -2.0};
  p.innerRadius = 1.5;
  p.outerRadius = 4.0;
  p.angle = 120.0;
  p.radialDivisions = 3;
  p.circumferentialDivisions = 4;
  p.radialGrading = 2.0;
  p.elementType = tc.type;
  const Mesh mesh = generateRingSector(p);
  const double cx = 1.0, cy = -2.0, a = 1.5, b = 4.0;

  test::expectGeneratedBlock(mesh, tc);
  EXPECT_EQ(estimateElements(p), double(tc.cells));

  // Every node lies on one of the grid's circles (order 2: also the circles halfway between)
  // and rays: mid-side nodes of circumferential edges are on the arcs, at their middle.
  const int order = info(tc.cellType).order;
  const auto radii = ringSectorRadii(a, b, 3, 2.0);
  EXPECT_NEAR((radii[3] - radii[2]) / (radii[1] - radii[0]), 2.0, 1e-12);
  std::vector<double> circles(radii), rays;
  if (order == 2)
    for (int i = 0; i < 3; ++i)
      circles.push_back(0.5 * (radii[i] + radii[i + 1]));
  for (int j = 0; j <= 4 * order; ++j)
    rays.push_back(120.0 * j / (4 * order));
  for (std::size_t n = 0; n < mesh.numNodes(); ++n) {
    const auto x = test::node(mesh, n);
    EXPECT_GE(radius(x, cx, cy), a - 1e-12);
    EXPECT_LE(radius(x, cx, cy), b + 1e-12);
    EXPECT_TRUE(onGrid(radius(x, cx, cy), circles, b))
        << "node " << n << " r " << radius(x, cx, cy);
    EXPECT_TRUE(onGrid(degrees(x, cx, cy), rays, 360)) << "node " << n;
  }

  // Corner-based cell areas make the inscribed polygon; the isoparametric quadratic cells
  // follow the parabolas through each arc's ends and middle, within O(dtheta^4) of the sector.
  const double dtheta = 120.0 / 4 * M_PI / 180;
  const double sector = dtheta * 4 / 2 * (b * b - a * a);
  EXPECT_NEAR(test::blockMeasure(mesh, "body"), polygonArea(4, dtheta, a, b), 1e-12 * sector);
  const double iso = order == 2 ? parabolicArea(4, dtheta, a, b) : polygonArea(4, dtheta, a, b);
  EXPECT_NEAR(isoparametricArea(mesh), iso, 1e-12 * sector);
  if (order == 2) {
    EXPECT_NEAR(isoparametricArea(mesh), sector, 2e-4 * sector);  // 30 degree arcs
  }

  const std::vector<std::string> names{"start",
                                       "outer",
                                       "end",
                                       "inner",
                                       "corner-inner-start",
                                       "corner-outer-start",
                                       "corner-outer-end",
                                       "corner-inner-end"};
  EXPECT_EQ(mesh.boundaryNames(), names);
  for (const auto& [side, facets] :
       {std::pair{"inner", 4}, std::pair{"outer", 4}, std::pair{"start", 3}, std::pair{"end", 3}}) {
    const auto groups = mesh.findBoundaries(side);
    ASSERT_EQ(groups.size(), 1u);
    EXPECT_EQ(groups[0]->type, tc.lineType);
    EXPECT_EQ(groups[0]->size(), static_cast<std::size_t>(facets));
    EXPECT_EQ(mesh.boundaryNodes(side).size(), static_cast<std::size_t>(order * facets + 1));
  }
  for (auto n : mesh.boundaryNodes("inner"))
    EXPECT_NEAR(radius(test::node(mesh, n), cx, cy), a, 1e-12);
  for (auto n : mesh.boundaryNodes("outer"))
    EXPECT_NEAR(radius(test::node(mesh, n), cx, cy), b, 1e-12);
  for (auto n : mesh.boundaryNodes("start"))
    EXPECT_EQ(test::node(mesh, n)[1], cy);  // exactly on the x axis through the centre
  for (auto n : mesh.boundaryNodes("end"))
    EXPECT_NEAR(degrees(test::node(mesh, n), cx, cy), 120.0, 1e-12);
  for (const auto& [corner, r, deg] :
       {std::tuple{"corner-inner-start", a, 0.0}, std::tuple{"corner-outer-start", b, 0.0},
        std::tuple{"corner-outer-end", b, 120.0}, std::tuple{"corner-inner-end", a, 120.0}}) {
    const auto n = mesh.boundaryNodes(corner);
    ASSERT_EQ(n.size(), 1u);
    EXPECT_NEAR(radius(test::node(mesh, n[0]), cx, cy), r, 1e-12) << corner;
    EXPECT_NEAR(degrees(test::node(mesh, n[0]), cx, cy), deg, 1e-12) << corner;
  }
}

// 3 x 4 divisions: 12 cells (24 triangles); 4 * 5 = 20 grid points at order 1, 7 * 9 = 63 at
// order 2, less the 12 cell centres for quad8.
INSTANTIATE_TEST_SUITE_P(AllTypes, RingSectorGenerator,
                         ::testing::ValuesIn(test::generatorCases2D(12, 20, 51, 63)),
                         [](const auto& info) { return info.param.type; });

// The default quarter ring: every boundary facet's normal points out of the body (pressure
// loads need it), nodes on the axes have a coordinate exactly 0.
TEST(RingSectorGenerator, QuarterRingHasExactAxisNodesAndOutwardFacets) {
  RingSectorParams p;  // a = 1, b = 2, 90 degrees, quad8
  const Mesh mesh = generateRingSector(p);
  // A 2D facet's normal is (t_y, -t_x) for t from its node 0 to its node 1 (IsoparametricMap).
  for (const auto& [side, inward] :
       {std::pair{"inner", std::array<double, 2>{}}, std::pair{"outer", std::array<double, 2>{}},
        std::pair{"start", std::array<double, 2>{0, 1}},
        std::pair{"end", std::array<double, 2>{1, 0}}}) {
    const auto& g = *mesh.findBoundaries(side).at(0);
    for (std::size_t f = 0; f < g.size(); ++f) {
      const auto x0 = test::node(mesh, g.nodes[f * g.nodesPerCell()]);
      const auto x1 = test::node(mesh, g.nodes[f * g.nodesPerCell() + 1]);
      const double n[2] = {x1[1] - x0[1], x0[0] - x1[0]};
      // Into the body: towards larger r from the inner circle, smaller r from the outer one.
      std::array<double, 2> in = inward;
      if (side == std::string("inner")) in = {x0[0] + x1[0], x0[1] + x1[1]};
      if (side == std::string("outer")) in = {-x0[0] - x1[0], -x0[1] - x1[1]};
      EXPECT_LT(n[0] * in[0] + n[1] * in[1], 0) << side << " facet " << f;
    }
  }
  for (auto n : mesh.boundaryNodes("end"))
    EXPECT_EQ(test::node(mesh, n)[0], 0.0);
  for (auto n : mesh.boundaryNodes("start"))
    EXPECT_EQ(test::node(mesh, n)[1], 0.0);
  EXPECT_NEAR(isoparametricArea(mesh), parabolicArea(4, M_PI / 8, 1, 2), 1e-12);
  EXPECT_NEAR(isoparametricArea(mesh), 0.75 * M_PI, 6e-5 * 0.75 * M_PI);  // 22.5 degree arcs
}

// Angle = 360 closes the ring: the seam's nodes are shared, no 'start' / 'end'.
TEST(RingSectorGenerator, FullRingSharesTheSeam) {
  RingSectorParams p;
  p.angle = 360.0;
  p.radialDivisions = 2;
  p.circumferentialDivisions = 8;
  p.elementType = "quad9";
  const Mesh mesh = generateRingSector(p);
  EXPECT_EQ(mesh.numNodes(), 5u * 16u);
  EXPECT_EQ(mesh.numElements(), 16u);
  EXPECT_GT(test::minJacobian(mesh), 0.0);
  EXPECT_NEAR(isoparametricArea(mesh), parabolicArea(8, M_PI / 4, 1, 2), 1e-12);
  const std::vector<std::string> names{"outer", "inner", "corner-inner-start",
                                       "corner-outer-start"};
  EXPECT_EQ(mesh.boundaryNames(), names);
  // Every node belongs to some element (none left over from the seam).
  EXPECT_EQ(test::blockNodes(mesh, "body").size(), mesh.numNodes());
  EXPECT_EQ(mesh.boundaryNodes("inner").size(), 16u);
}

std::string messageOf(const RingSectorParams& p) {
  try {
    generateRingSector(p);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

TEST(RingSectorGeneratorErrors, NameTheParameter) {
  using Change = std::function<void(RingSectorParams&)>;
  const std::vector<std::pair<Change, std::string>> cases{
      {[](auto& p) { p.innerRadius = 0; }, "Inner Radius = 0 must be a positive number"},
      {[](auto& p) { p.outerRadius = 1; }, "Outer Radius = 1 must be larger than Inner Radius = 1"},
      {[](auto& p) { p.radialDivisions = 0; }, "Radial Divisions = 0 must be at least 1"},
      {[](auto& p) { p.circumferentialDivisions = 0; },
       "Circumferential Divisions = 0 must be at least 1"},
      {[](auto& p) { p.angle = 200, p.circumferentialDivisions = 2; },
       "Circumferential Divisions = 2 must be at least 3 for Angle = 200: an element spans at "
       "most 90 degrees"},
      {[](auto& p) { p.radialGrading = -1; }, "Radial Grading = -1 must be a positive number"},
      {[](auto& p) { p.elementType = "hex8"; },
       "element type 'hex8' is not supported; valid choices: tri3, tri6, quad4, quad8, quad9"}};
  for (const auto& [change, message] : cases) {
    RingSectorParams p;
    change(p);
    EXPECT_EQ(messageOf(p), "ring-sector generator: " + message);
  }
  for (double angle : {0.0, -90.0, 360.5, std::nan("")}) {
    RingSectorParams p;
    p.angle = angle;
    EXPECT_NE(messageOf(p).find("Angle = "), std::string::npos) << angle;
    EXPECT_NE(messageOf(p).find("must lie in (0, 360] degrees"), std::string::npos) << angle;
  }
}

}  // namespace
}  // namespace contactlab
