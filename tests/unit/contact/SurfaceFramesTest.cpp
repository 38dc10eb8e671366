// Surface frames: tangent bases and nodal normals with known answers.
#include "core/contact/SurfaceFrames.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

TEST(TangentBasis, OrthonormalAndRightHandedIn3D) {
  const double s = 1 / std::sqrt(3.0);
  for (const std::array<double, 3>& n : std::vector<std::array<double, 3>>{
           {0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}, {s, s, s}, {0.6, 0, 0.8}}) {
    std::array<double, 3> t1, t2;
    tangentBasis(3, n, t1, t2);
    EXPECT_NEAR(dot(t1, t1), 1, 1e-15);
    EXPECT_NEAR(dot(t2, t2), 1, 1e-15);
    EXPECT_NEAR(dot(t1, n), 0, 1e-15);
    EXPECT_NEAR(dot(t2, n), 0, 1e-15);
    EXPECT_NEAR(dot(t1, t2), 0, 1e-15);
    // n x t1 = t2: (t1, t2, n) is right-handed.
    const std::array<double, 3> c{n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2],
                                  n[0] * t1[1] - n[1] * t1[0]};
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(c[i], t2[i], 1e-15);
  }
}

// A normal on the tie |n_x| = |n_y| (a node on a symmetric mesh's diagonal): two updates whose
// round-off orders n_x and n_y differently turn tangentBasis's t1 by some 84 degrees; the following
// frame keeps its axis, and is tangentBasis's own frame wherever that axis is the chosen one.
TEST(TangentBasis, TheFollowingFrameDoesNotTurnOnATie) {
  const auto unit = [](std::array<double, 3> v) {
    const double norm = std::sqrt(dot(v, v));
    for (double& c : v)
      c /= norm;
    return v;
  };
  const auto xFirst = unit({0.3, 0.3 + 1e-12, 0.9}), yFirst = unit({0.3 + 1e-12, 0.3, 0.9});
  std::array<double, 3> a1, a2, b1, b2;
  tangentBasis(3, xFirst, a1, a2);
  tangentBasis(3, yFirst, b1, b2);
  EXPECT_LT(std::abs(dot(a1, b1)), 0.2);  // turned by more than 78 degrees
  std::array<double, 3> f1 = a1, f2 = a2;
  tangentBasisFollowing(3, yFirst, f1, f2);
  EXPECT_GT(dot(a1, f1), 1 - 1e-12);
  EXPECT_GT(dot(a2, f2), 1 - 1e-12);
  EXPECT_NEAR(dot(f1, yFirst), 0, 1e-15);
  // Where the kept axis is the least aligned one, the same frame to the last bit.
  std::array<double, 3> g1 = b1, g2 = b2;
  tangentBasisFollowing(3, yFirst, g1, g2);
  EXPECT_EQ(g1, b1);
  EXPECT_EQ(g2, b2);
  // A first frame (t1 = 0) is tangentBasis's; an axis turned close to n is given up.
  std::array<double, 3> z1{}, z2{};
  tangentBasisFollowing(3, xFirst, z1, z2);
  EXPECT_EQ(z1, a1);
  const auto nearX = unit({0.95, 0.2, 0.1});
  std::array<double, 3> h1 = a1, h2 = a2, r1, r2;
  tangentBasisFollowing(3, nearX, h1, h2);
  tangentBasis(3, nearX, r1, r2);
  EXPECT_EQ(h1, r1);
}

TEST(TangentBasis, RotatedNormalIn2D) {
  std::array<double, 3> t1, t2;
  tangentBasis(2, {0.6, 0.8, 0}, t1, t2);
  EXPECT_NEAR(t1[0], -0.8, 1e-15);
  EXPECT_NEAR(t1[1], 0.6, 1e-15);
  EXPECT_EQ(dot(t2, t2), 0.0);
}

// A regular polygon inscribed in a circle: the average of the two facet normals at a vertex is
// the radial direction exactly.
TEST(NodalNormals, RadialOnARegularPolygon) {
  const int n = 12;
  std::vector<Facet> facets;
  std::vector<std::int64_t> nodes;
  for (int k = 0; k < n; ++k) {
    const double a0 = 2 * M_PI * k / n, a1 = 2 * M_PI * (k + 1) / n;
    // Counter-clockwise polygon: the facet normal (t_y, -t_x) points outwards.
    facets.push_back(
        {ElementType::Line2, {std::cos(a0), std::sin(a0), 0, std::cos(a1), std::sin(a1), 0}, k});
    nodes.push_back(k);
    nodes.push_back((k + 1) % n);
  }
  const auto normals = nodalNormals(facets, nodes);
  ASSERT_EQ(normals.size(), static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    EXPECT_NEAR(normals.at(k)[0], std::cos(a), 1e-14) << k;
    EXPECT_NEAR(normals.at(k)[1], std::sin(a), 1e-14) << k;
  }
}

// Two triangles folded along the x axis (a roof): the ridge nodes get the bisector, the others
// their own facet's normal.
TEST(NodalNormals, BisectorOnARidge) {
  const double c = std::cos(0.3), s = std::sin(0.3);
  std::vector<Facet> facets = {
      {ElementType::Tri3, {0, 0, 0, 1, 0, 0, 0, c, s}, 1},    // y > 0 side, tilted up
      {ElementType::Tri3, {0, 0, 0, 0, -c, s, 1, 0, 0}, 2}};  // y < 0 side
  std::vector<std::int64_t> nodes = {0, 1, 2, 0, 3, 1};
  const auto normals = nodalNormals(facets, nodes);
  EXPECT_NEAR(normals.at(0)[0], 0, 1e-15);
  EXPECT_NEAR(normals.at(0)[1], 0, 1e-15);
  EXPECT_NEAR(normals.at(0)[2], 1, 1e-15);  // the two normals (0, -s, c), (0, s, c) average to z
  EXPECT_NEAR(normals.at(2)[1], -s, 1e-15);
  EXPECT_NEAR(normals.at(2)[2], c, 1e-15);
}

}  // namespace
}  // namespace contactlab
