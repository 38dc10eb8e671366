// Weighted surface measures (core/contact/SurfaceWeight.hpp): an axisymmetric model's contact
// surfaces are rings, dA w(x) with w = 2 pi r. The tributary areas and the mortar integrals must
// then be the ring's, in closed form for a segment r in [r0, r1] of the line z = 0.
#include "tests/unit/contact/MortarTestSupport.hpp"

#include "core/contact/MortarIntegration.hpp"
#include "core/contact/TributaryAreas.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>

namespace contactlab {
namespace {

const SurfaceWeight kRing = [](const double* x) { return 2.0 * M_PI * x[0]; };

TEST(SurfaceWeight, TributaryAreasOfARingSumToItsArea) {
  // The bottom r in [1, 4] of a rectangle, 3 line2 segments: the ring's area pi (4^2 - 1^2).
  RectangleParams p;
  p.origin = {1.0, 0.0};
  p.lengths = {3.0, 1.0};
  p.divisions = {3, 1};
  const Mesh mesh = generateRectangle(p);
  const auto w = tributaryAreas(mesh, "bottom", 2, referencePositions(mesh), kRing);
  ASSERT_EQ(w.size(), 4u);
  double sum = 0.0;
  for (const auto& [node, value] : w) {
    EXPECT_GT(value, 0.0);
    sum += value;
  }
  EXPECT_NEAR(sum, M_PI * 15.0, 1e-12 * sum);
  // HRZ on the segment [1, 2]: int N_a^2 2 pi r dr is 2 pi (5/12) at r = 1 and 2 pi (7/12) at
  // r = 2, scaled to the segment's ring area 3 pi: 1.25 pi and 1.75 pi; the end node r = 1
  // has only that share.
  for (const auto& [node, value] : w)
    if (std::abs(mesh.coords[3 * node] - 1.0) < 1e-12) {
      EXPECT_NEAR(value, 1.25 * M_PI, 1e-12);
    }
}

TEST(SurfaceWeight, MortarIntegralsOfARing) {
  // Slave r in [1, 2] on z = 0 against the same segment traversed the other way round.
  const auto map = [](double u, double) { return test::Vec3{1.5 + 0.5 * u, 0.0, 0.0}; };
  const Facet slave = test::makeFacet(ElementType::Line2, map);
  const std::vector<Facet> masters{test::makeMaster(ElementType::Line2, map)};
  const auto normals = test::nodeNormals(slave);
  // Standard basis: D_jk = int N_j N_k 2 pi r dr, e.g. D_00 = 2 pi int_0^1 (1 - s)^2 (1 + s) ds.
  const MortarIntegrals standard =
      integrateMortar(slave, normals, test::pointers(masters), MultiplierBasis::Standard, kRing);
  const double D[4] = {2 * M_PI * 5.0 / 12.0, 2 * M_PI * 0.25, 2 * M_PI * 0.25,
                       2 * M_PI * 7.0 / 12.0};
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(standard.D[k], D[k], 1e-13) << k;
  EXPECT_NEAR(standard.area, 3 * M_PI, 1e-13);
  EXPECT_NEAR(standard.coveredArea, 3 * M_PI, 1e-13);
  // Dual basis: D diagonal, int N_j 2 pi r dr = 2 pi (2/3) and 2 pi (5/6).
  const MortarIntegrals dual =
      integrateMortar(slave, normals, test::pointers(masters), MultiplierBasis::Dual, kRing);
  EXPECT_NEAR(dual.D[0], 2 * M_PI * 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(dual.D[3], 2 * M_PI * 5.0 / 6.0, 1e-12);
  EXPECT_NEAR(dual.D[1], 0.0, 1e-12);
  EXPECT_NEAR(dual.D[2], 0.0, 1e-12);
  // A 3D facet has no ring: refused.
  const auto square = [](double u, double v) { return test::Vec3{u, v, 0.0}; };
  const Facet quad = test::makeFacet(ElementType::Quad4, square);
  const std::vector<Facet> quadMasters{test::makeMaster(ElementType::Quad4, square)};
  EXPECT_THROW(integrateMortar(quad, test::nodeNormals(quad), test::pointers(quadMasters),
                               MultiplierBasis::Standard, kRing),
               std::invalid_argument);
}

}  // namespace
}  // namespace contactlab
