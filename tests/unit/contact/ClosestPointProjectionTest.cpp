#include "core/contact/ClosestPointProjection.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace contactlab {
namespace {

const double kPi = std::acos(-1.0);
const int kDistortedFacets = 8;
const int kPointsPerFacet = 12;

bool isSimplex(ElementType t) {
  return t == ElementType::Tri3 || t == ElementType::Tri6;
}

void position(ElementType t, const std::vector<double>& x, const double* xi, double* p) {
  const auto& ref = ReferenceElement::get(t);
  double N[9];
  ref.shape(xi, N);
  for (int i = 0; i < 3; ++i) {
    p[i] = 0.0;
    for (int a = 0; a < ref.numNodes(); ++a)
      p[i] += N[a] * x[3 * a + i];
  }
}

double distanceAt(ElementType t, const std::vector<double>& x, const double* xi, const double* xs) {
  double p[3];
  position(t, x, xi, p);
  return std::sqrt((p[0] - xs[0]) * (p[0] - xs[0]) + (p[1] - xs[1]) * (p[1] - xs[1]) +
                   (p[2] - xs[2]) * (p[2] - xs[2]));
}

struct Brute {
  double xi[2] = {0.0, 0.0};
  double distance = std::numeric_limits<double>::infinity();
};

// Minimum distance over the reference facet by dense sampling, refined around the best sample
// seven times (the final spacing is ~1e-9 in reference coordinates).
Brute bruteForce(ElementType t, const std::vector<double>& x, const double* xs) {
  const int dim = ReferenceElement::get(t).dim();
  const bool simplex = isSimplex(t);
  const double lo = simplex ? 0.0 : -1.0, hi = 1.0;
  Brute best;
  double centre[2] = {0.5 * (lo + hi), dim > 1 ? 0.5 * (lo + hi) : 0.0};
  double half = 0.5 * (hi - lo);
  int n = 400;
  for (int round = 0; round < 8; ++round) {
    const double h = 2 * half / n;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= (dim > 1 ? n : 0); ++j) {
        double xi[2] = {std::clamp(centre[0] - half + i * h, lo, hi),
                        dim > 1 ? std::clamp(centre[1] - half + j * h, lo, hi) : 0.0};
        if (simplex && xi[0] + xi[1] > 1.0) {  // onto the hypotenuse, which gets sampled too
          const double excess = 0.5 * (xi[0] + xi[1] - 1.0);
          xi[0] -= excess, xi[1] -= excess;
          if (xi[0] < 0.0 || xi[1] < 0.0) continue;
        }
        const double d = distanceAt(t, x, xi, xs);
        if (d < best.distance) best.distance = d, best.xi[0] = xi[0], best.xi[1] = xi[1];
      }
    centre[0] = best.xi[0], centre[1] = best.xi[1];
    half = 2 * h;
    n = 40;
  }
  return best;
}

// Reference nodes of t mapped through f(xi, eta) -> (x, y, z).
template <class F>
std::vector<double> mappedNodes(ElementType t, F f) {
  const auto& ref = ReferenceElement::get(t);
  const int d = ref.dim();
  std::vector<double> x(3 * ref.numNodes());
  for (int a = 0; a < ref.numNodes(); ++a) {
    const double* r = &ref.nodeCoordinates()[a * d];
    f(r[0], d > 1 ? r[1] : 0.0, &x[3 * a]);
  }
  return x;
}

// A twisted spherical cap (radius 2), normal +z: a smooth doubly curved surface.
void cap(double u, double v, double* p) {
  p[0] = u + 0.1 * v * v;
  p[1] = v + 0.05 * u;
  p[2] = std::sqrt(4.0 - u * u - v * v) - 2.0;
}

void expectValid(const Projection& p) {
  for (double v : {p.xi[0], p.xi[1], p.point[0], p.point[1], p.point[2], p.normal[0], p.normal[1],
                   p.normal[2], p.gap, p.distance})
    EXPECT_TRUE(std::isfinite(v));
  EXPECT_NEAR(
      std::sqrt(p.normal[0] * p.normal[0] + p.normal[1] * p.normal[1] + p.normal[2] * p.normal[2]),
      1.0, 1e-12);
}

void expectMatchesBruteForce(ElementType t, const std::vector<double>& x, const double* xs,
                             const Projection& p, double relTol = 0.0) {
  const Brute b = bruteForce(t, x, xs);
  const double tol = 1e-8 + relTol * b.distance;
  EXPECT_NEAR(p.distance, b.distance, tol)
      << "xs = " << xs[0] << " " << xs[1] << " " << xs[2] << "; xi = " << p.xi[0] << " " << p.xi[1]
      << " (inside " << p.inside << "), sampled xi = " << b.xi[0] << " " << b.xi[1];
  EXPECT_LE(p.distance, b.distance + 1e-12 + relTol * b.distance);
  EXPECT_NEAR(p.distance, distanceAt(t, x, p.xi, xs), 1e-12 * (1 + p.distance));
  EXPECT_TRUE(insideReferenceFacet(t, p.xi));
}

TEST(ClosestPointProjection, Line2PointAboveAndPenetrating) {
  // Traversed from (2, 0) to (0, 0): t = (-2, 0) / 2, n = (t_y, -t_x) / |t| = (0, 1).
  const std::vector<double> x = {2, 0, 0, 0, 0, 0};
  const double above[3] = {0.5, 0.3, 0};
  Projection p = projectOnFacet(ElementType::Line2, 2, x.data(), above);
  EXPECT_TRUE(p.converged);
  EXPECT_TRUE(p.inside);
  EXPECT_NEAR(p.xi[0], 0.5, 1e-14);
  EXPECT_NEAR(p.point[0], 0.5, 1e-14);
  EXPECT_NEAR(p.point[1], 0.0, 1e-14);
  EXPECT_NEAR(p.normal[0], 0.0, 1e-14);
  EXPECT_NEAR(p.normal[1], 1.0, 1e-14);
  EXPECT_NEAR(p.gap, 0.3, 1e-14);
  EXPECT_NEAR(p.distance, 0.3, 1e-14);
  EXPECT_LE(p.iterations, 2);

  const double below[3] = {1.5, -0.1, 0};
  p = projectOnFacet(ElementType::Line2, 2, x.data(), below);
  EXPECT_TRUE(p.inside);
  EXPECT_NEAR(p.xi[0], -0.5, 1e-14);
  EXPECT_NEAR(p.gap, -0.1, 1e-14);
  EXPECT_NEAR(p.distance, 0.1, 1e-14);
}

TEST(ClosestPointProjection, Line2BeyondEndClampsToVertex) {
  const std::vector<double> x = {2, 0, 0, 0, 0, 0};
  const double beyond0[3] = {3, 0.4, 0};
  Projection p = projectOnFacet(ElementType::Line2, 2, x.data(), beyond0);
  EXPECT_TRUE(p.converged);
  EXPECT_FALSE(p.inside);
  EXPECT_DOUBLE_EQ(p.xi[0], -1.0);
  EXPECT_NEAR(p.point[0], 2.0, 1e-14);
  EXPECT_NEAR(p.point[1], 0.0, 1e-14);
  EXPECT_NEAR(p.distance, std::sqrt(1.16), 1e-14);
  EXPECT_NEAR(p.gap, 0.4, 1e-14);

  const double beyond1[3] = {-1, -0.2, 0};
  p = projectOnFacet(ElementType::Line2, 2, x.data(), beyond1);
  EXPECT_FALSE(p.inside);
  EXPECT_DOUBLE_EQ(p.xi[0], 1.0);
  EXPECT_NEAR(p.point[0], 0.0, 1e-14);
  EXPECT_NEAR(p.gap, -0.2, 1e-14);
}

TEST(ClosestPointProjection, Line3CircularArc) {
  // Unit circle, arc from -30 to +30 degrees traversed counter-clockwise: n outward.
  const double R = 1.0, a0 = -kPi / 6, a1 = kPi / 6;
  const std::vector<double> x = {
      R * std::cos(a0), R * std::sin(a0), 0, R * std::cos(a1), R * std::sin(a1), 0, R, 0, 0};
  for (double phi : {0.0, 0.2, -0.4}) {
    for (double r : {1.2, 0.9, 0.2, 3.0}) {
      const double xs[3] = {r * std::cos(phi), r * std::sin(phi), 0};
      const Projection p = projectOnFacet(ElementType::Line3, 2, x.data(), xs);
      expectValid(p);
      EXPECT_TRUE(p.converged);
      EXPECT_TRUE(p.inside);
      EXPECT_LE(p.iterations, r < 0.5 ? 8 : 6);  // near the centre of curvature f is flat
      // Against the exact circle, within the quadratic interpolation's accuracy.
      EXPECT_NEAR(p.gap, r - R, 3e-3) << phi << " " << r;
      if (std::fabs(r - R) < 0.5) {  // far from the curve, small shape errors move the point
        EXPECT_NEAR(p.normal[0], std::cos(phi), 2e-2) << phi << " " << r;
        EXPECT_NEAR(p.normal[1], std::sin(phi), 2e-2) << phi << " " << r;
      }
      EXPECT_NEAR(std::fabs(p.gap), p.distance, 1e-12);
      EXPECT_EQ(p.gap > 0, r > R);
      // Against the quadratic curve itself, exactly.
      expectMatchesBruteForce(ElementType::Line3, x, xs, p);
    }
  }
  // Beyond the arc's end: clamped to node 1.
  const double xs[3] = {0.0, 1.5, 0.0};
  const Projection p = projectOnFacet(ElementType::Line3, 2, x.data(), xs);
  EXPECT_FALSE(p.inside);
  EXPECT_DOUBLE_EQ(p.xi[0], 1.0);
  expectMatchesBruteForce(ElementType::Line3, x, xs, p);
}

TEST(ClosestPointProjection, FlatQuad4) {
  const std::vector<double> x = {0, 0, 1, 2, 0, 1, 2, 3, 1, 0, 3, 1};
  const double xs[3] = {0.5, 2.0, 1.7};
  const Projection p = projectOnFacet(ElementType::Quad4, 3, x.data(), xs);
  EXPECT_TRUE(p.converged);
  EXPECT_TRUE(p.inside);
  EXPECT_NEAR(p.xi[0], -0.5, 1e-14);
  EXPECT_NEAR(p.xi[1], 1.0 / 3.0, 1e-14);
  EXPECT_NEAR(p.point[2], 1.0, 1e-14);
  EXPECT_NEAR(p.normal[2], 1.0, 1e-14);
  EXPECT_NEAR(p.gap, 0.7, 1e-14);
  EXPECT_LE(p.iterations, 2);

  // Beyond the corner (2, 3) and below: clamped to the corner, penetrating side.
  const double corner[3] = {2.5, 4.0, 0.5};
  const Projection q = projectOnFacet(ElementType::Quad4, 3, x.data(), corner);
  EXPECT_FALSE(q.inside);
  EXPECT_NEAR(q.xi[0], 1.0, 1e-12);
  EXPECT_NEAR(q.xi[1], 1.0, 1e-12);
  EXPECT_NEAR(q.gap, -0.5, 1e-12);
  // Beyond the edge y = 0: clamped onto the edge.
  const double edge[3] = {1.2, -0.5, 1.1};
  const Projection e = projectOnFacet(ElementType::Quad4, 3, x.data(), edge);
  EXPECT_FALSE(e.inside);
  EXPECT_TRUE(e.converged);
  EXPECT_NEAR(e.xi[0], 0.2, 1e-12);
  EXPECT_NEAR(e.xi[1], -1.0, 1e-12);
  EXPECT_NEAR(e.distance, std::sqrt(0.25 + 0.01), 1e-12);
}

TEST(ClosestPointProjection, TiltedTri3) {
  const double p0[3] = {1, 0, 0}, p1[3] = {0, 1, 0}, p2[3] = {0, 0, 1};
  const std::vector<double> x = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const double s = 1 / std::sqrt(3.0), n[3] = {s, s, s};
  auto at = [&](double u, double v, double h, double* xs) {
    for (int i = 0; i < 3; ++i)
      xs[i] = p0[i] + u * (p1[i] - p0[i]) + v * (p2[i] - p0[i]) + h * n[i];
  };
  double xs[3];
  at(1.0 / 3, 1.0 / 3, 0.5, xs);
  Projection p = projectOnFacet(ElementType::Tri3, 3, x.data(), xs);
  EXPECT_TRUE(p.inside);
  EXPECT_NEAR(p.xi[0], 1.0 / 3, 1e-14);
  EXPECT_NEAR(p.xi[1], 1.0 / 3, 1e-14);
  EXPECT_NEAR(p.gap, 0.5, 1e-14);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(p.normal[i], n[i], 1e-14);

  at(0.2, 0.3, -0.1, xs);
  p = projectOnFacet(ElementType::Tri3, 3, x.data(), xs);
  EXPECT_TRUE(p.inside);
  EXPECT_NEAR(p.xi[0], 0.2, 1e-14);
  EXPECT_NEAR(p.xi[1], 0.3, 1e-14);
  EXPECT_NEAR(p.gap, -0.1, 1e-14);

  // In-plane beyond the edge 1-2 (through its midpoint, perpendicular to it), then lifted.
  const double m[3] = {0, 0.5, 0.5}, dn = std::sqrt(1.5), d[3] = {-1 / dn, 0.5 / dn, 0.5 / dn};
  for (int i = 0; i < 3; ++i)
    xs[i] = m[i] + 0.3 * d[i] + 0.2 * n[i];
  p = projectOnFacet(ElementType::Tri3, 3, x.data(), xs);
  EXPECT_FALSE(p.inside);
  EXPECT_TRUE(p.converged);
  EXPECT_NEAR(p.xi[0], 0.5, 1e-12);
  EXPECT_NEAR(p.xi[1], 0.5, 1e-12);
  EXPECT_NEAR(p.gap, 0.2, 1e-12);
  EXPECT_NEAR(p.distance, std::sqrt(0.13), 1e-12);

  // Beyond vertex 0, away from the centroid: clamped to the vertex.
  for (int i = 0; i < 3; ++i)
    xs[i] = p0[i] + 0.5 * (p0[i] - 1.0 / 3) - 0.1 * n[i];
  p = projectOnFacet(ElementType::Tri3, 3, x.data(), xs);
  EXPECT_FALSE(p.inside);
  EXPECT_NEAR(p.xi[0], 0.0, 1e-12);
  EXPECT_NEAR(p.xi[1], 0.0, 1e-12);
  EXPECT_NEAR(p.gap, -0.1, 1e-12);
}

TEST(ClosestPointProjection, DistortedNonPlanarQuad4) {
  const std::vector<double> x = {0, 0, 0, 1, 0, 0.3, 1.2, 1, -0.1, 0, 1.1, 0.4};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.5, 1.7), w(-0.8, 0.8);
  int inside = 0;
  for (int k = 0; k < 60; ++k) {
    const double xs[3] = {u(rng), u(rng), w(rng)};
    const Projection p = projectOnFacet(ElementType::Quad4, 3, x.data(), xs);
    expectValid(p);
    EXPECT_TRUE(p.converged);
    expectMatchesBruteForce(ElementType::Quad4, x, xs, p);
    if (p.inside) {
      ++inside;
      EXPECT_NEAR(std::fabs(p.gap), p.distance, 1e-10);
      EXPECT_LE(p.iterations, 8);
    }
  }
  EXPECT_GT(inside, 10);
}

class CurvedFacet : public ::testing::TestWithParam<ElementType> {};

TEST_P(CurvedFacet, MatchesDenseSamplingAndConvergesQuadratically) {
  const ElementType t = GetParam();
  const auto x = mappedNodes(t, cap);
  std::mt19937 rng(11);
  const bool simplex = isSimplex(t);
  std::uniform_real_distribution<double> u(simplex ? -0.4 : -1.6, simplex ? 1.0 : 1.6),
      w(-1.0, 0.6);
  int inside = 0, outside = 0, maxIterationsInside = 0;
  for (int k = 0; k < 80; ++k) {
    const double xs[3] = {u(rng), u(rng), w(rng)};
    const Projection p = projectOnFacet(t, 3, x.data(), xs);
    expectValid(p);
    EXPECT_TRUE(p.converged);
    expectMatchesBruteForce(t, x, xs, p);
    if (p.inside) {
      ++inside;
      maxIterationsInside = std::max(maxIterationsInside, p.iterations);
      EXPECT_NEAR(std::fabs(p.gap), p.distance, 1e-10);
    } else {
      ++outside;
    }
  }
  EXPECT_GT(inside, 10);
  EXPECT_GT(outside, 10);
  EXPECT_LE(maxIterationsInside, 6);

  // Points near the surface above and below: the gap sign follows the side.
  const double xi[2] = {isSimplex(t) ? 0.2 : 0.4, isSimplex(t) ? 0.5 : -0.3};
  double p0[3];
  position(t, x, xi, p0);
  for (double h : {0.05, -0.05}) {
    const double xs[3] = {p0[0], p0[1], p0[2] + h};
    const Projection p = projectOnFacet(t, 3, x.data(), xs);
    EXPECT_TRUE(p.inside);
    EXPECT_EQ(p.gap > 0, h > 0);
    EXPECT_NEAR(std::fabs(p.gap), std::fabs(h), 0.01);
  }
}

INSTANTIATE_TEST_SUITE_P(Facets, CurvedFacet,
                         ::testing::Values(ElementType::Quad8, ElementType::Quad9,
                                           ElementType::Tri6, ElementType::Quad4,
                                           ElementType::Tri3),
                         [](const ::testing::TestParamInfo<ElementType>& i) {
                           return std::string(contactlab::info(i.param).name);
                         });

TEST_P(CurvedFacet, RandomlyDistortedFacetsMatchDenseSampling) {
  const ElementType t = GetParam();
  const bool simplex = isSimplex(t);
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> jitter(-0.12, 0.12), u(simplex ? -0.5 : -1.8, 1.8),
      w(-1.2, 0.8);
  int maxIterationsInside = 0;
  for (int facet = 0; facet < kDistortedFacets; ++facet) {
    auto x = mappedNodes(t, cap);
    for (double& c : x)
      c += jitter(rng);
    for (int k = 0; k < kPointsPerFacet; ++k) {
      const double xs[3] = {u(rng), u(rng), w(rng)};
      const Projection p = projectOnFacet(t, 3, x.data(), xs);
      expectValid(p);
      EXPECT_TRUE(p.converged);
      expectMatchesBruteForce(t, x, xs, p);
      if (p.inside) maxIterationsInside = std::max(maxIterationsInside, p.iterations);
    }
  }
  EXPECT_LE(maxIterationsInside, 10);
}

// Quadratic convergence: once the Newton step is below 1e-3, at most three more iterations bring
// it below 1e-12 (a linear rate would need many more).
TEST(ClosestPointProjection, Quad9ConvergesQuadratically) {
  const auto x = mappedNodes(ElementType::Quad9, cap);
  for (const auto& xs :
       {std::vector<double>{0.55, -0.4, 0.35}, std::vector<double>{-0.8, 0.6, -0.3},
        std::vector<double>{0.1, 0.9, 0.8}}) {
    const Projection loose = projectOnFacet(ElementType::Quad9, 3, x.data(), xs.data(), 1e-3);
    const Projection tight = projectOnFacet(ElementType::Quad9, 3, x.data(), xs.data(), 1e-12);
    ASSERT_TRUE(loose.inside && tight.inside);
    EXPECT_LE(tight.iterations - loose.iterations, 3);
    EXPECT_LE(tight.iterations, 6);
    EXPECT_NEAR(loose.xi[0], tight.xi[0], 1e-5);
    EXPECT_NEAR(loose.xi[1], tight.xi[1], 1e-5);
  }
}

TEST(ClosestPointProjection, Quad9NewtonIterationsFromCentre) {
  const auto x = mappedNodes(ElementType::Quad9, cap);
  // Slave points on the normals of points spread over the facet (normal by finite differences):
  // Newton from the centre finds them back in a few iterations (quadratic rate).
  const double e = 1e-6;
  for (double a : {-0.9, -0.5, 0.0, 0.6, 0.95})
    for (double b : {-0.8, 0.0, 0.7})
      for (double h : {0.3, -0.2}) {
        const double xi[2] = {a, b}, xa[2] = {a + e, b}, xb[2] = {a - e, b}, xc[2] = {a, b + e},
                     xd[2] = {a, b - e};
        double q[3], pa[3], pb[3], pc[3], pd[3];
        position(ElementType::Quad9, x, xi, q);
        position(ElementType::Quad9, x, xa, pa);
        position(ElementType::Quad9, x, xb, pb);
        position(ElementType::Quad9, x, xc, pc);
        position(ElementType::Quad9, x, xd, pd);
        const double t0[3] = {pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]};
        const double t1[3] = {pc[0] - pd[0], pc[1] - pd[1], pc[2] - pd[2]};
        double n[3] = {t0[1] * t1[2] - t0[2] * t1[1], t0[2] * t1[0] - t0[0] * t1[2],
                       t0[0] * t1[1] - t0[1] * t1[0]};
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        const double xs[3] = {q[0] + h * n[0] / len, q[1] + h * n[1] / len, q[2] + h * n[2] / len};
        const Projection p = projectOnFacet(ElementType::Quad9, 3, x.data(), xs);
        EXPECT_TRUE(p.converged);
        EXPECT_TRUE(p.inside) << a << " " << b << " " << h;
        EXPECT_LE(p.iterations, 6) << a << " " << b << " " << h;
        EXPECT_NEAR(p.xi[0], a, 1e-8);
        EXPECT_NEAR(p.xi[1], b, 1e-8);
        EXPECT_NEAR(p.gap, h, 1e-8);
        for (int i = 0; i < 3; ++i)
          EXPECT_NEAR(p.normal[i], n[i] / len, 1e-8);
      }
}

TEST(ClosestPointProjection, FarPointsConvergeWithoutNaN) {
  const std::vector<double> far = {1e3,  -2e3, 5e2, 1e6, 1,    1,    0, 0, 1e4,
                                   -1e5, 0,    0,   3,   -4e2, -7e2, 0, 0, -1e6};
  for (ElementType t : {ElementType::Tri3, ElementType::Tri6, ElementType::Quad4,
                        ElementType::Quad8, ElementType::Quad9}) {
    const auto x = mappedNodes(t, cap);
    for (std::size_t k = 0; k < far.size(); k += 3) {
      const Projection p = projectOnFacet(t, 3, x.data(), &far[k]);
      expectValid(p);
      EXPECT_TRUE(p.converged) << info(t).name << " " << k;
      EXPECT_TRUE(insideReferenceFacet(t, p.xi));
      expectMatchesBruteForce(t, x, &far[k], p, 1e-13);
    }
  }
  for (ElementType t : {ElementType::Line2, ElementType::Line3}) {
    const auto x = mappedNodes(
        t, [](double u, double, double* p) { p[0] = u, p[1] = 0.3 * u * u, p[2] = 0.0; });
    const double pts[4][3] = {{1e6, 3e5, 0}, {-2e4, -1e6, 0}, {0, 1e5, 0}, {5, -1e3, 0}};
    for (const auto& xs : pts) {
      const Projection p = projectOnFacet(t, 2, x.data(), xs);
      expectValid(p);
      EXPECT_TRUE(p.converged);
      expectMatchesBruteForce(t, x, xs, p, 1e-13);
    }
  }
}

TEST(ClosestPointProjection, RejectsNonFacetTypes) {
  const std::vector<double> x(27, 0.0);
  const double xs[3] = {0, 0, 0};
  EXPECT_THROW(projectOnFacet(ElementType::Quad4, 2, x.data(), xs), std::invalid_argument);
  EXPECT_THROW(projectOnFacet(ElementType::Line2, 3, x.data(), xs), std::invalid_argument);
  EXPECT_THROW(projectOnFacet(ElementType::Hex8, 3, x.data(), xs), std::invalid_argument);
}

}  // namespace
}  // namespace contactlab

namespace contactlab {
namespace {

// Inside a facet the extension's projection is the projection; past its boundary it continues
// the same polynomial surface (the clamped projection stops at the boundary).
TEST(ProjectOnFacetExtension, AgreesInsideAndContinuesOutside) {
  // A curved line3 from (0,0) to (2,0) bulging to y = 0.2 at its middle node.
  const double line[9] = {0, 0, 0, 2, 0, 0, 1, 0.2, 0};
  const double inside[3] = {0.7, 0.9, 0};
  const Projection a = projectOnFacet(ElementType::Line3, 2, line, inside);
  const double start[2] = {0.0, 0.0};
  const Projection b = projectOnFacetExtension(ElementType::Line3, 2, line, inside, start);
  ASSERT_TRUE(b.converged);
  EXPECT_NEAR(a.xi[0], b.xi[0], 1e-12);
  EXPECT_NEAR(a.gap, b.gap, 1e-12);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(a.normal[i], b.normal[i], 1e-12);
  const double outside[3] = {2.3, 0.5, 0};
  const Projection c = projectOnFacetExtension(ElementType::Line3, 2, line, outside, start);
  ASSERT_TRUE(c.converged);
  EXPECT_GT(c.xi[0], 1.0);
  EXPECT_FALSE(c.inside);
  // Stationary: the distance vector is normal to the tangent there.
  const double t[2] = {c.normal[1], -c.normal[0]};
  EXPECT_NEAR((outside[0] - c.point[0]) * t[0] + (outside[1] - c.point[1]) * t[1], 0.0, 1e-12);
  // A quad4 in 3D, slightly warped.
  const double quad[12] = {0, 0, 0, 1, 0, 0.1, 1, 1, 0, 0, 1, 0.05};
  const double p[3] = {0.3, 0.6, 0.4};
  const Projection d = projectOnFacet(ElementType::Quad4, 3, quad, p);
  const Projection e = projectOnFacetExtension(ElementType::Quad4, 3, quad, p, start);
  ASSERT_TRUE(e.converged);
  EXPECT_NEAR(d.xi[0], e.xi[0], 1e-10);
  EXPECT_NEAR(d.xi[1], e.xi[1], 1e-10);
  EXPECT_NEAR(d.gap, e.gap, 1e-12);
}

}  // namespace
}  // namespace contactlab
