// Mortar integrals of one slave facet against master facets that cover it in part, lie off
// its plane, are tilted or curved, or are rotated with the mesh: the covered area is the known
// one and the transfer of fields holds; degenerate input is refused.
#include "tests/unit/contact/MortarTestSupport.hpp"

#include "core/contact/MortarIntegration.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>
#include <vector>

namespace contactlab {
namespace {

using namespace test;

// ---- 5. Partial overlap ----

TEST(MortarIntegration, PartialOverlapCoversTheIntersection) {
  const Facet slave = makeFacet(ElementType::Quad4, unitSlave(ElementType::Quad4));
  const auto square = [](double x, double y) {
    return [=](double u, double v) { return place({x + 0.5 + 0.5 * u, y + 0.5 + 0.5 * v, 0}); };
  };
  const std::vector<Facet> masters = {makeMaster(ElementType::Quad4, square(3, 0)),
                                      makeMaster(ElementType::Quad4, square(0.5, 0.5))};
  for (MultiplierBasis basis : kBases) {
    const MortarIntegrals r = integrateMortar(slave, nodeNormals(slave), pointers(masters), basis);
    EXPECT_NEAR(r.coveredArea, 0.25, 1e-15);
    ASSERT_EQ(r.masters.size(), 1u);
    EXPECT_EQ(r.masters[0].facet, 1u);
    expectTransfer(slave, masters, r, linearField, 1e-14);
  }

  const Facet line = makeFacet(ElementType::Line2, unitSlave(ElementType::Line2));
  const auto segment = [](double x) {
    return makeMaster(ElementType::Line2, [=](double u, double) {
      return Vec3{x + 0.5 * u, 0, 0};
    });
  };
  const std::vector<Facet> segments = {segment(1), segment(3)};
  const MortarIntegrals r =
      integrateMortar(line, nodeNormals(line), pointers(segments), MultiplierBasis::Standard);
  EXPECT_NEAR(r.coveredArea, 0.5, 1e-15);
  ASSERT_EQ(r.masters.size(), 1u);
  EXPECT_EQ(r.masters[0].facet, 0u);
}

// On a partially covered facet the dual basis is built on the covered part: D stays diagonal
// and holds the standard basis' covered integrals, and each row of M sums to its D entry (a
// uniform pressure is still transferred exactly). The whole facet's basis would couple the
// nodes and give a near-zero weight to the node the master barely reaches. (On quadratic
// facets a corner function integrates to a negative value over this covered part: no covered
// basis, the whole facet's is kept; the transfer of a constant is checked for those.)
TEST(MortarIntegration, DualBasisOnACoveredPartStaysBiorthogonal) {
  for (ElementType t :
       {ElementType::Line2, ElementType::Line3, ElementType::Quad4, ElementType::Tri3,
        ElementType::Tri6, ElementType::Quad8, ElementType::Quad9}) {
    const Facet slave = makeFacet(t, unitSlave(t));
    // A master shifted by a third of the slave's extent along x: it covers part of it.
    const Map shifted = [&](double u, double v) {
      Vec3 x = unitSlave(t)(u, v);
      x[0] += 0.3;
      return x;
    };
    const std::vector<Facet> masters = {makeMaster(t, shifted)};
    const MortarIntegrals standard =
        integrateMortar(slave, nodeNormals(slave), pointers(masters), MultiplierBasis::Standard);
    const MortarIntegrals dual =
        integrateMortar(slave, nodeNormals(slave), pointers(masters), MultiplierBasis::Dual);
    SCOPED_TRACE(info(t).name);
    ASSERT_NEAR(standard.coveredArea, dual.coveredArea, 1e-14);
    ASSERT_GT(dual.coveredArea, 0.3 * dual.area);
    ASSERT_LT(dual.coveredArea, 0.9 * dual.area);
    ASSERT_EQ(dual.masters.size(), 1u);
    expectTransfer(slave, masters, dual, constantField, 1e-12);
    if (info(t).order > 1) continue;
    const int n = info(t).nodes;
    const int nm = static_cast<int>(dual.masters[0].M.size()) / n;
    for (int j = 0; j < n; ++j) {
      double covered = 0.0, masterSum = 0.0;
      for (int k = 0; k < n; ++k) {
        covered += standard.D[j * n + k];
        if (k != j) {
          EXPECT_NEAR(dual.D[j * n + k], 0.0, 1e-12);
        }
      }
      for (int l = 0; l < nm; ++l)
        masterSum += dual.masters[0].M[j * nm + l];
      EXPECT_NEAR(dual.D[j * n + j], covered, 1e-12);
      EXPECT_NEAR(masterSum, dual.D[j * n + j], 1e-12);
    }
  }
}

// ---- 6. Projection, not proximity ----

TEST(MortarIntegration, OffsetAlongTheNormalChangesNothing) {
  for (const PatchCase& c : {kPatchCases[0], kPatchCases[6]}) {
    const Facet slave = makeFacet(c.slave, unitSlave(c.slave));
    const std::vector<Facet> near = patchMasters(c), far = patchMasters(c, 0.37);
    const MortarIntegrals a =
        integrateMortar(slave, nodeNormals(slave), pointers(near), MultiplierBasis::Dual);
    const MortarIntegrals b =
        integrateMortar(slave, nodeNormals(slave), pointers(far), MultiplierBasis::Dual);
    ASSERT_EQ(a.masters.size(), b.masters.size());
    for (std::size_t k = 0; k < a.D.size(); ++k)
      EXPECT_NEAR(a.D[k], b.D[k], 1e-14);
    for (std::size_t m = 0; m < a.masters.size(); ++m) {
      EXPECT_EQ(a.masters[m].facet, b.masters[m].facet);
      for (std::size_t k = 0; k < a.masters[m].M.size(); ++k)
        EXPECT_NEAR(a.masters[m].M[k], b.masters[m].M[k], 1e-14);
    }
  }
}

// ---- 7. Non-coplanar facets and a rotated mesh ----

TEST(MortarIntegration, TiltedMastersStillCoverTheSlave) {
  for (ElementType t : {ElementType::Quad4, ElementType::Tri3, ElementType::Quad9}) {
    const Facet slave = makeFacet(t, unitSlave(t));
    const std::vector<Facet> masters =
        masterGrid(ElementType::Quad4, 3, -0.3, 1.3, 7 * kPi / 180, 0.05,
                   {std::sqrt(0.5), std::sqrt(0.5), 0}, 2 * kPi / 180);
    for (MultiplierBasis basis : kBases) {
      const MortarIntegrals r =
          integrateMortar(slave, nodeNormals(slave), pointers(masters), basis);
      EXPECT_NEAR(r.coveredArea, r.area, 1e-12) << info(t).name;
      expectTransfer(slave, masters, r, constantField, 1e-10);
    }
  }
}

// Curved slaves, integrated up to the quadrature error of their non-polynomial area element.
// 3D: a quad9 bulging out of its plane (straight edges in projection), so that the clip
// polygons are the projection of the curved facet and dA_plane / |n_S . n0| recovers its area.
TEST(MortarIntegration, CurvedSlaveIsIntegratedOnItsSurface) {
  const Facet slave = makeFacet(ElementType::Quad9, [](double u, double v) {
    return place({0.5 + 0.5 * u, 0.5 + 0.5 * v, 0.1 * (1 - u * u) * (1 - v * v)});
  });
  const std::vector<Facet> masters = masterGrid(ElementType::Quad4, 3, -0.3, 1.3, 7 * kPi / 180);
  std::vector<Vec3> normals(9, place({0, 0, 1}));
  const Vec3 origin = place({0, 0, 0});
  for (Vec3& n : normals)
    for (int i = 0; i < 3; ++i)
      n[i] -= origin[i];
  const MortarIntegrals r =
      integrateMortar(slave, normals, pointers(masters), MultiplierBasis::Standard);
  const double area = facetMatrices(slave).area;
  EXPECT_GT(area, 1.02);
  EXPECT_NEAR(r.area, area, 1e-7);
  EXPECT_NEAR(r.coveredArea, area, 1e-8);
  expectTransfer(slave, masters, r, constantField, 1e-12);

  // 2D: a curved line3 slave projecting along its varying nodal normals (Newton in xi).
  const Facet arc = makeFacet(ElementType::Line3, [](double u, double) {
    return Vec3{0.5 + 0.5 * u, -0.15 * (1 - u * u), 0};
  });
  const std::vector<Facet> segments = masterGrid(ElementType::Line2, 3, -0.4, 1.3, 0, 0.1);
  for (MultiplierBasis basis : kBases) {
    const MortarIntegrals r2 = integrateMortar(arc, nodeNormals(arc), pointers(segments), basis);
    // Arc length of (0.5 + 0.5 u, -0.15 (1 - u^2)): 2 int_0^1 sqrt(a^2 + b^2 u^2) du.
    const double a = 0.5, b = 0.3, length = std::hypot(a, b) + a * a / b * std::asinh(b / a);
    EXPECT_NEAR(r2.area, length, 1e-8);
    EXPECT_NEAR(r2.coveredArea, length, 1e-8);
    expectTransfer(arc, segments, r2, constantField, 1e-14);
  }
}

// A far master is not an overlap: on a curved line3 slave the normal lines through the
// extrapolated facet (|xi| >> 1, where the interpolated normals swing) can meet a distant
// master's two ends on both sides of the slave, which read as covering it all. Coordinates of
// cattaneo-mindlin-2d at the contact edge in its normal step (a nearly flat slave whose nodal
// normals turn by 5e-3 across it; a master 0.25 away).
TEST(MortarIntegration, DistantMasterOnACurvedSlaveIsNoOverlap) {
  Facet slave{ElementType::Line3,
              {0.064379099625611544, -0.010000442261974808, 0, 0.073634907432162292,
               -0.010003483931826516, 0, 0.06900450931698357, -0.010001138685165461, 0}};
  const std::vector<Vec3> normals = {{-3.5380609641833154e-05, -0.99999999937410622, 0},
                                     {-0.0051098628159435208, -0.99998694456577897, 0},
                                     {-0.00032862282266874599, -0.99999994600351882, 0}};
  const std::vector<Facet> far = {
      {ElementType::Line3,
       {0.37605145505157628, -0.075253050798442064, 0, 0.31103183685935021, -0.052017484387009642,
        0, 0.34374774768616617, -0.063058125691514283, 0}}};
  const std::vector<Facet> near = {
      {ElementType::Line3,
       {0.073654982874933814, -0.010005410137985959, 0, 0.064373152926862132,
        -0.0099999847126556272, 0, 0.069003128276117612, -0.010000780929000107, 0}}};
  for (MultiplierBasis basis : kBases) {
    const MortarIntegrals r = integrateMortar(slave, normals, pointers(far), basis);
    EXPECT_EQ(r.coveredArea, 0.0);
    EXPECT_TRUE(r.masters.empty());
    const MortarIntegrals covered = integrateMortar(slave, normals, pointers(near), basis);
    EXPECT_NEAR(covered.coveredArea, covered.area, 1e-3 * covered.area);
    EXPECT_EQ(covered.masters.size(), 1u);
  }
}

// doc/verification.md V3's rotated case: the hex faces of a 5 x 5 block top against a 3 x 3 block
// bottom rotated by 5 degrees about the vertical axis through the centre. The union of the cells
// is the overlap of the two unit squares: 1 - (c + s - 1)^2 / (2 c s) (four corner triangles cut).
TEST(MortarIntegration, RotatedMeshCoversTheSquaresOverlap) {
  const double angle = 5 * kPi / 180, c = std::cos(angle), s = std::sin(angle);
  const std::vector<Facet> masters = masterGrid(ElementType::Quad4, 3, 0, 1, angle);
  double covered = 0.0;
  int full = 0;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      const Facet slave = makeFacet(ElementType::Quad4, [=](double u, double v) {
        return place({(i + 0.5 * (u + 1)) / 5, (j + 0.5 * (v + 1)) / 5, 0});
      });
      const MortarIntegrals r =
          integrateMortar(slave, nodeNormals(slave), pointers(masters), MultiplierBasis::Dual);
      covered += r.coveredArea;
      expectTransfer(slave, masters, r, constantField, 1e-15);
      expectTransfer(slave, masters, r, linearField, 1e-14);
      if (i > 0 && i < 4 && j > 0 && j < 4) {
        EXPECT_NEAR(r.coveredArea, r.area, 1e-15);
        ++full;
      }
    }
  EXPECT_EQ(full, 9);
  EXPECT_NEAR(covered, 1 - (c + s - 1) * (c + s - 1) / (2 * c * s), 1e-14);
}

// ---- Invalid input ----

TEST(MortarIntegration, RejectsDegenerateInput) {
  const Facet square = makeFacet(ElementType::Quad4, unitSlave(ElementType::Quad4));
  const Facet flat{ElementType::Quad4, {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0}, 7};
  const Facet point{ElementType::Line2, {1, 1, 0, 1, 1, 0}, 8};
  const Facet line = makeFacet(ElementType::Line2, unitSlave(ElementType::Line2));
  const auto standard = MultiplierBasis::Standard;
  EXPECT_THROW(integrateMortar(flat, nodeNormals(square), {&square}, standard),
               std::invalid_argument);
  EXPECT_THROW(integrateMortar(square, nodeNormals(square), {&flat}, standard),
               std::invalid_argument);
  EXPECT_THROW(integrateMortar(line, nodeNormals(line), {&point}, standard), std::invalid_argument);
  EXPECT_THROW(integrateMortar(square, nodeNormals(square), {&line}, standard),
               std::invalid_argument);
  EXPECT_THROW(integrateMortar(square, nodeNormals(line), {&square}, standard),
               std::invalid_argument);
  // Nodal normals in the slave's plane: no auxiliary plane, no projection direction.
  const Vec3 o = place({0, 0, 0}), e = place({1, 0, 0});
  EXPECT_THROW(
      integrateMortar(square, std::vector<Vec3>(4, {e[0] - o[0], e[1] - o[1], e[2] - o[2]}),
                      {&square}, standard),
      std::invalid_argument);
  EXPECT_THROW(integrateMortar(line, std::vector<Vec3>(2, {1, 0, 0}), {&line}, standard),
               std::invalid_argument);
}

}  // namespace
}  // namespace contactlab