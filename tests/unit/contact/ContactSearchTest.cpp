#include "core/contact/BoundingBoxTree.hpp"
#include "core/contact/ContactSearch.hpp"
#include "core/mesh/Mesh.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <random>
#include <stdexcept>
#include <vector>

namespace contactlab {
namespace {

const double kSqrt2 = std::sqrt(2.0);

Facet line2(double x0, double y0, double x1, double y1) {
  return Facet{ElementType::Line2, {x0, y0, 0.0, x1, y1, 0.0}, -1};
}

// Flat line y = 0, x in [0, n], facets ordered right to left so the normal is +y.
std::vector<Facet> flatLine(int n) {
  std::vector<Facet> facets;
  for (int i = 0; i < n; ++i)
    facets.push_back(line2(i + 1.0, 0.0, i, 0.0));
  return facets;
}

// n x n quad4 grid of [0, L]^2 in z = 0, counter-clockwise (normal +z).
std::vector<Facet> flatQuads(int n, double L) {
  std::vector<Facet> facets;
  const double h = L / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = i * h, y = j * h;
      facets.push_back(Facet{ElementType::Quad4,
                             {x, y, 0, x + h, y, 0, x + h, y + h, 0, x, y + h, 0},
                             static_cast<std::int64_t>(facets.size())});
    }
  return facets;
}

// Sphere of radius R, parameters u (longitude, along xi) and v (latitude, along eta): x_u x x_v
// points outward, so the facet normal is outward.
void spherePoint(double R, double u, double v, double* x) {
  x[0] = R * std::cos(v) * std::cos(u);
  x[1] = R * std::cos(v) * std::sin(u);
  x[2] = R * std::sin(v);
}

// Patch u in [0, 1], v in [-0.5, 0.5] of n x n cells: quad9 cells, or each cell split into two
// tri6 (gmsh order: corners, then mid-sides 01, 12, 20); every node lies on the sphere.
std::vector<Facet> spherePatch(double R, int n, bool triangles) {
  std::vector<Facet> facets;
  const double du = 1.0 / n, dv = 1.0 / n;
  auto push = [&](ElementType t, const std::vector<std::pair<double, double>>& uv) {
    Facet f{t, std::vector<double>(3 * uv.size()), static_cast<std::int64_t>(facets.size())};
    for (std::size_t a = 0; a < uv.size(); ++a)
      spherePoint(R, uv[a].first, uv[a].second, &f.coords[3 * a]);
    facets.push_back(std::move(f));
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u0 = i * du, u1 = u0 + du, um = u0 + du / 2;
      const double v0 = -0.5 + j * dv, v1 = v0 + dv, vm = v0 + dv / 2;
      if (!triangles) {
        push(ElementType::Quad9, {{u0, v0},
                                  {u1, v0},
                                  {u1, v1},
                                  {u0, v1},
                                  {um, v0},
                                  {u1, vm},
                                  {um, v1},
                                  {u0, vm},
                                  {um, vm}});
      } else {
        push(ElementType::Tri6, {{u0, v0}, {u1, v0}, {u1, v1}, {um, v0}, {u1, vm}, {um, vm}});
        push(ElementType::Tri6, {{u0, v0}, {u1, v1}, {u0, v1}, {um, vm}, {um, v1}, {u0, vm}});
      }
    }
  return facets;
}

std::vector<double> randomBoxes(std::mt19937& rng, int n, double maxSize) {
  std::uniform_real_distribution<double> pos(0.0, 10.0), ext(0.0, maxSize);
  std::vector<double> boxes(6 * n);
  for (int i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) {
      boxes[6 * i + d] = pos(rng);
      boxes[6 * i + 3 + d] = boxes[6 * i + d] + ext(rng);
    }
  return boxes;
}

TEST(BoundingBoxTree, QueriesMatchBruteForce) {
  std::mt19937 rng(7);
  const int n = 1000;
  const std::vector<double> boxes = randomBoxes(rng, n, 1.0);
  const BoundingBoxTree tree(boxes);
  const std::vector<double> queries = randomBoxes(rng, 200, 2.0);
  std::vector<std::size_t> found;
  std::size_t total = 0;
  for (int q = 0; q < 200; ++q) {
    const double* qb = &queries[6 * q];
    std::vector<std::size_t> expected;
    for (int i = 0; i < n; ++i) {
      bool hit = true;
      for (int d = 0; d < 3; ++d)
        hit = hit && boxes[6 * i + d] <= qb[3 + d] && boxes[6 * i + 3 + d] >= qb[d];
      if (hit) expected.push_back(i);
    }
    tree.intersecting(qb, found);
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, expected) << "box query " << q;
    total += expected.size();

    // Point query: centre of the query box, radius 0.7.
    const double p[3] = {qb[0], qb[1], qb[2]};
    expected.clear();
    for (int i = 0; i < n; ++i)
      if (BoundingBoxTree::squaredDistance(&boxes[6 * i], p) <= 0.49) expected.push_back(i);
    tree.withinDistance(p, 0.7, found);
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, expected) << "point query " << q;
    total += expected.size();
  }
  EXPECT_GT(total, 200u);  // the queries are not all empty
}

TEST(BoundingBoxTree, EmptyDegenerateAndInvalid) {
  std::vector<std::size_t> out{42};
  const double q[6] = {0, 0, 0, 1, 1, 1};
  BoundingBoxTree().intersecting(q, out);
  EXPECT_TRUE(out.empty());
  // 100 000 identical boxes: the median split by count keeps the tree balanced.
  const BoundingBoxTree same(std::vector<double>(6 * 100000, 0.5));
  same.withinDistance(q, 1.0, out);
  EXPECT_EQ(out.size(), 100000u);
  EXPECT_THROW(BoundingBoxTree(std::vector<double>(5)), std::invalid_argument);
  EXPECT_THROW(BoundingBoxTree(std::vector<double>{1, 0, 0, 0, 0, 0}), std::invalid_argument);
}

TEST(ContactSearch, FlatLine2D) {
  const ContactSearch search(flatLine(10), 0.5);
  for (int i = 0; i < 10; ++i) {
    const double xs[3] = {i + 0.3, 0.2, 0.0};
    const Pairing p = search.findClosest(xs);
    ASSERT_TRUE(p.found);
    EXPECT_EQ(p.facet, static_cast<std::size_t>(i));
    EXPECT_TRUE(p.projection.inside);
    EXPECT_NEAR(p.projection.gap, 0.2, 1e-12);
    EXPECT_NEAR(p.projection.point[0], i + 0.3, 1e-12);
    EXPECT_NEAR(p.projection.normal[1], 1.0, 1e-12);
    EXPECT_LE(p.candidates, 3);
  }
  // Penetrating point: negative gap.
  const double below[3] = {4.5, -0.1, 0.0};
  EXPECT_NEAR(search.findClosest(below).projection.gap, -0.1, 1e-12);
  // Beyond the right end, within reach: the end node, outside the facet.
  const double beyond[3] = {10.3, 0.1, 0.0};
  const Pairing end = search.findClosest(beyond);
  ASSERT_TRUE(end.found);
  EXPECT_EQ(end.facet, 9u);
  EXPECT_FALSE(end.projection.inside);
  EXPECT_NEAR(end.projection.point[0], 10.0, 1e-12);
  EXPECT_NEAR(end.projection.distance, std::hypot(0.3, 0.1), 1e-12);
  EXPECT_EQ(end.sharedBy, 1);
  // Too far beyond the end, too far above: not found (surfaces that never meet).
  const double farEnd[3] = {10.6, 0.0, 0.0}, farAbove[3] = {5.0, 0.6, 0.0};
  EXPECT_FALSE(search.findClosest(farEnd).found);
  EXPECT_FALSE(search.findClosest(farAbove).found);
  const double veryFar[3] = {1e3, 1e3, 0.0};
  EXPECT_EQ(search.findClosest(veryFar).candidates, 0);
}

TEST(ContactSearch, ConvexKink2D) {
  // Roof /\ with apex at the origin, normals pointing up-left and up-right.
  const ContactSearch search({line2(0, 0, -1, -1), line2(1, -1, 0, 0)}, 2.0);
  for (double x : {0.0, 0.1, -0.2}) {
    const double xs[3] = {x, 1.0, 0.0};
    const Pairing p = search.findClosest(xs);
    ASSERT_TRUE(p.found);
    EXPECT_FALSE(p.projection.inside);
    EXPECT_EQ(p.sharedBy, 2);
    EXPECT_NEAR(p.projection.point[0], 0.0, 1e-12);
    EXPECT_NEAR(p.projection.point[1], 0.0, 1e-12);
    EXPECT_NEAR(p.projection.normal[0], 0.0, 1e-12);  // average of (-1,1) and (1,1)
    EXPECT_NEAR(p.projection.normal[1], 1.0, 1e-12);
    EXPECT_NEAR(p.projection.gap, std::hypot(x, 1.0), 1e-12);
  }
  // Within the normal cone of the right facet: an ordinary inside projection.
  const double right[3] = {0.8, 0.0, 0.0};
  const Pairing p = search.findClosest(right);
  EXPECT_EQ(p.facet, 1u);
  EXPECT_TRUE(p.projection.inside);
  EXPECT_NEAR(p.projection.gap, 0.8 / kSqrt2, 1e-12);
  // Penetrating below the apex: inside a facet, negative gap.
  const double under[3] = {0.1, -0.3, 0.0};
  EXPECT_LT(search.findClosest(under).projection.gap, 0.0);
}

TEST(ContactSearch, ConcaveKink2D) {
  // Valley \/ with bottom at the origin, normals pointing into the valley.
  const ContactSearch search({line2(0, 0, -1, 1), line2(1, 1, 0, 0)}, 2.0);
  const double xs[3] = {0.1, 0.5, 0.0};  // projects inside both facets
  const Pairing p = search.findClosest(xs);
  ASSERT_TRUE(p.found);
  EXPECT_EQ(p.candidates, 2);
  EXPECT_EQ(p.facet, 1u);
  EXPECT_TRUE(p.projection.inside);
  EXPECT_NEAR(p.projection.distance, 0.4 / kSqrt2, 1e-12);
  EXPECT_NEAR(p.projection.gap, 0.4 / kSqrt2, 1e-12);
  const double mirrored[3] = {-0.1, 0.5, 0.0};
  EXPECT_EQ(search.findClosest(mirrored).facet, 0u);
}

TEST(ContactSearch, FlatQuads3D) {
  const ContactSearch search(flatQuads(10, 1.0), 0.2);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> in(0.0, 1.0), height(-0.15, 0.15);
  for (int k = 0; k < 200; ++k) {
    const double xs[3] = {in(rng), in(rng), height(rng)};
    const Pairing p = search.findClosest(xs);
    ASSERT_TRUE(p.found);
    EXPECT_TRUE(p.projection.inside);
    EXPECT_NEAR(p.projection.gap, xs[2], 1e-12);
    EXPECT_NEAR(p.projection.point[0], xs[0], 1e-12);
    EXPECT_NEAR(p.projection.point[1], xs[1], 1e-12);
    const int i = std::min(9, static_cast<int>(xs[0] * 10)),
              j = std::min(9, static_cast<int>(xs[1] * 10));
    EXPECT_EQ(p.facet, static_cast<std::size_t>(10 * i + j)) << xs[0] << " " << xs[1];
  }
  const double above[3] = {0.5, 0.5, 0.25};
  EXPECT_FALSE(search.findClosest(above).found);
}

TEST(ContactSearch, CurvedSpherePatch) {
  const double R = 2.0;
  for (bool triangles : {false, true}) {
    const ContactSearch search(spherePatch(R, 8, triangles), 0.5);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.05, 0.95), v(-0.45, 0.45), dr(-0.3, 0.4);
    for (int k = 0; k < 100; ++k) {
      const double r = R + dr(rng);
      double xs[3];
      spherePoint(r, u(rng), v(rng), xs);
      const Pairing p = search.findClosest(xs);
      ASSERT_TRUE(p.found) << (triangles ? "tri6" : "quad9");
      // Quadratic interpolation of an arc of 1/8 rad: |x - sphere| ~ R h^3 / 100 ~ 1e-5.
      EXPECT_NEAR(p.projection.gap, r - R, 2e-4) << (triangles ? "tri6" : "quad9");
      EXPECT_NEAR(std::abs(p.projection.gap), p.projection.distance, 1e-12);
    }
    // Beyond the search distance along a ray: not found.
    double far[3];
    spherePoint(R + 0.6, 0.5, 0.0, far);
    EXPECT_FALSE(search.findClosest(far).found);
  }
}

TEST(ContactSearch, CandidatesGrowLikeLogN) {
  const int n = 100;  // 10 000 facets, h = 0.01
  const ContactSearch search(flatQuads(n, 1.0), 0.01);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> in(0.0, 1.0), height(-0.005, 0.005);
  std::vector<double> points(3 * 10000);
  for (double& x : points)
    x = in(rng);
  for (std::size_t k = 2; k < points.size(); k += 3)
    points[k] = height(rng);
  int maxProjections = 0, found = 0;
  long total = 0;
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < points.size(); k += 3) {
    const Pairing p = search.findClosest(&points[k]);
    maxProjections = std::max(maxProjections, p.projections);
    total += p.projections;
    found += p.found;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ info ] 1e4 queries on 1e4 facets: %.3f s, projections/query: mean %.1f, max %d\n",
              seconds, total / 1e4, maxProjections);
  EXPECT_EQ(found, 10000);
  EXPECT_LE(maxProjections, 30);
}

TEST(ContactSearch, FacetsOfMeshGroup) {
  Mesh mesh;
  mesh.dim = 2;
  mesh.coords = {0, 0, 0, 1, 0, 0, 2, 0, 0};
  CellGroup top;
  top.name = "top";
  top.dim = 1;
  top.type = ElementType::Line2;
  top.nodes = {1, 0, 2, 1};
  top.tags = {7, 8};
  mesh.boundaries.push_back(top);
  const std::vector<Facet> facets = facetsOf(mesh, "top");
  ASSERT_EQ(facets.size(), 2u);
  EXPECT_EQ(facets[1].tag, 8);
  EXPECT_EQ(facets[1].coords, (std::vector<double>{2, 0, 0, 1, 0, 0}));
  EXPECT_THROW(facetsOf(mesh, "nope"), std::invalid_argument);
  const double xs[3] = {1.5, 0.25, 0.0};
  const Pairing p = ContactSearch(facets, 1.0).findClosest(xs);
  EXPECT_EQ(p.facet, 1u);
  EXPECT_NEAR(p.projection.gap, 0.25, 1e-12);
  EXPECT_THROW(ContactSearch(facets, -1.0), std::invalid_argument);
  EXPECT_THROW(ContactSearch({Facet{ElementType::Tri3, {0, 0, 0}, 0}}, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace contactlab
