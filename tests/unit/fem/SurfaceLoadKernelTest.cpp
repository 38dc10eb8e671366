#include "tests/unit/fem/FemTestSupport.hpp"

#include "core/problem/SurfaceLoadKernel.hpp"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <stdexcept>

namespace contactlab {
namespace {

using test::nameOf;

const ElementType kFacets3d[] = {ElementType::Tri3, ElementType::Tri6, ElementType::Quad4,
                                 ElementType::Quad8, ElementType::Quad9};

// Flat facet in the plane through o spanned by the orthonormal e1, e2: tensor cells cover
// [0,3]x[0,2], triangles the half with legs 3 and 2. Normal e1 x e2.
std::vector<double> flatFacet(ElementType t) {
  const double o[3] = {1, 2, 3};
  const double e1[3] = {0.6, 0.8, 0}, e2[3] = {0, 0, 1};  // normal (0.8, -0.6, 0)
  const auto& ref = ReferenceElement::get(t);
  std::vector<double> x(3 * ref.numNodes());
  for (int a = 0; a < ref.numNodes(); ++a) {
    const double* xi = &ref.nodeCoordinates()[2 * a];
    const double s = test::isSimplex(t) ? 3 * xi[0] : 1.5 * (xi[0] + 1);
    const double r = test::isSimplex(t) ? 2 * xi[1] : xi[1] + 1;
    for (int i = 0; i < 3; ++i)
      x[3 * a + i] = o[i] + s * e1[i] + r * e2[i];
  }
  return x;
}

TEST(SurfaceLoadKernel, UniformPressureOnFlatFacetsSumsToPAlongMinusN) {
  const double n[3] = {0.8, -0.6, 0}, p = 2.5;
  for (ElementType t : kFacets3d) {
    SurfaceLoadKernel kernel(t, 3);
    const auto x = flatFacet(t);
    const double area = test::isSimplex(t) ? 3.0 : 6.0;
    EXPECT_NEAR(kernel.area(x.data()), area, 1e-13) << nameOf(t);
    std::vector<double> f(kernel.numDofs());
    kernel.pressure(x.data(), p, f.data());
    for (int i = 0; i < 3; ++i) {
      double sum = 0;
      for (int a = 0; a < kernel.numNodes(); ++a)
        sum += f[3 * a + i];
      EXPECT_NEAR(sum, -p * area * n[i], 1e-12) << nameOf(t);
    }
    // Same as the traction -p n.
    std::vector<double> g(kernel.numDofs());
    const double tr[3] = {-p * n[0], -p * n[1], -p * n[2]};
    kernel.traction(x.data(), tr, g.data());
    for (int k = 0; k < kernel.numDofs(); ++k)
      EXPECT_NEAR(f[k], g[k], 1e-12) << nameOf(t);
  }
}

TEST(SurfaceLoadKernel, ConsistentNodalShares) {
  // Classic consistent loads of a uniform traction on flat undistorted facets, as fractions of
  // the total: line3 1/6 1/6 2/3; tri6 corners 0, mid-edges 1/3; quad8 corners -1/12,
  // mid-edges 1/3; quad9 1/36, 1/9, 4/9.
  struct Case {
    ElementType type;
    std::vector<double> share;
  };
  const Case cases[] = {
      {ElementType::Tri6, {0, 0, 0, 1. / 3, 1. / 3, 1. / 3}},
      {ElementType::Quad8,
       {-1. / 12, -1. / 12, -1. / 12, -1. / 12, 1. / 3, 1. / 3, 1. / 3, 1. / 3}},
      {ElementType::Quad9,
       {1. / 36, 1. / 36, 1. / 36, 1. / 36, 1. / 9, 1. / 9, 1. / 9, 1. / 9, 4. / 9}},
  };
  for (const auto& c : cases) {
    SurfaceLoadKernel kernel(c.type, 3);
    const auto x = flatFacet(c.type);
    const double area = kernel.area(x.data());
    std::vector<double> f(kernel.numDofs());
    const double tr[3] = {0, 0, 1};
    kernel.traction(x.data(), tr, f.data());
    for (int a = 0; a < kernel.numNodes(); ++a)
      EXPECT_NEAR(f[3 * a + 2], c.share[a] * area, 1e-13) << nameOf(c.type) << " node " << a;
  }
  SurfaceLoadKernel line(ElementType::Line3, 2);
  const std::vector<double> x = {0, 0, 0, 3, 0, 0, 1.5, 0, 0};
  std::vector<double> f(6);
  line.pressure(x.data(), 1.0, f.data());
  // Normal (0, -1): pressure pushes +y.
  EXPECT_NEAR(f[1], 0.5, 1e-14);
  EXPECT_NEAR(f[3], 0.5, 1e-14);
  EXPECT_NEAR(f[5], 2.0, 1e-14);
  EXPECT_NEAR(f[0] + f[2] + f[4], 0.0, 1e-14);
}

TEST(SurfaceLoadKernel, PressureOnCurvedFacetsIsExact) {
  // int n dA depends only on the boundary: (dy, -dx) for a curve, the enclosed planar area for
  // a dome over a flat square.
  SurfaceLoadKernel line(ElementType::Line3, 2);
  const double R = 2.0, s = R / std::sqrt(2.0);
  const std::vector<double> arc = {R, 0, 0, 0, R, 0, s, s, 0};
  std::vector<double> f(6);
  line.pressure(arc.data(), 3.0, f.data());
  EXPECT_NEAR(f[0] + f[2] + f[4], -3.0 * (R - 0), 1e-12);  // -p * dy
  EXPECT_NEAR(f[1] + f[3] + f[5], -3.0 * (R - 0), 1e-12);  // -p * (-dx) with dx = -R
  // Quad9 dome: corners (+-1, +-1, 0), mid-edges on z = 0, centre at z = 0.7.
  SurfaceLoadKernel dome(ElementType::Quad9, 3);
  const auto& ref = ReferenceElement::get(ElementType::Quad9);
  std::vector<double> x(27);
  for (int a = 0; a < 9; ++a) {
    x[3 * a] = ref.nodeCoordinates()[2 * a];
    x[3 * a + 1] = ref.nodeCoordinates()[2 * a + 1];
    x[3 * a + 2] = a == 8 ? 0.7 : 0.0;
  }
  std::vector<double> g(27);
  dome.pressure(x.data(), 2.0, g.data());
  double sum[3] = {};
  for (int a = 0; a < 9; ++a)
    for (int i = 0; i < 3; ++i)
      sum[i] += g[3 * a + i];
  EXPECT_NEAR(sum[0], 0.0, 1e-12);
  EXPECT_NEAR(sum[1], 0.0, 1e-12);
  EXPECT_NEAR(sum[2], -2.0 * 4.0, 1e-12);
  EXPECT_GT(dome.area(x.data()), 4.0);
}

TEST(SurfaceLoadKernel, PositionDependentLoads) {
  // Linear pressure p = x on the segment [0, 2] along x: total int p dx = 2 along -n = (0, 1).
  SurfaceLoadKernel line(ElementType::Line2, 2);
  const std::vector<double> x = {0, 0, 0, 2, 0, 0};
  std::vector<double> f(4);
  line.pressure(
      x.data(), [](const double* p) { return p[0]; }, f.data());
  EXPECT_NEAR(f[1], 2.0 / 3, 1e-14);
  EXPECT_NEAR(f[3], 4.0 / 3, 1e-14);
  line.traction(
      x.data(), [](const double* p, double* t) { t[0] = p[0], t[1] = 0, t[2] = 9; }, f.data());
  EXPECT_NEAR(f[0], 2.0 / 3, 1e-14);
  EXPECT_NEAR(f[2], 4.0 / 3, 1e-14);
  EXPECT_NEAR(f[1], 0.0, 1e-14);
}

// A facet of `type` in spaceDim = dim + 1 with curved reference nodes, and a random
// displacement of its nodes of size `amplitude` (a finite deformation of the facet).
struct DeformedFacet {
  std::vector<double> x, u;
};
// A ring (axisymmetric) is moved to x = r in [1.9, 2.1], off the axis.
DeformedFacet deformedFacet(ElementType type, std::mt19937& rng, double amplitude,
                            bool ring = false) {
  const int D = info(type).dim + 1;
  DeformedFacet d;
  const auto base = test::distortedNodes(type, 0.08);  // z = 0 for lines, 3D for surfaces
  d.x = base;
  if (D == 3)  // lift the surface out of its plane so that every normal component varies
    for (std::size_t a = 0; a < base.size() / 3; ++a)
      d.x[3 * a + 2] += 0.3 * base[3 * a] - 0.2 * base[3 * a + 1] * base[3 * a + 1];
  if (ring)
    for (std::size_t a = 0; a < base.size() / 3; ++a)
      d.x[3 * a] = 2.0 + 0.1 * base[3 * a];
  std::uniform_real_distribution<double> r(-amplitude, amplitude);
  d.u.resize(base.size() / 3 * D);
  for (double& v : d.u)
    v = r(rng);
  return d;
}

// The facets a follower pressure acts on, with the 2D lines also as axisymmetric rings.
const std::pair<ElementType, bool> kFollowerFacets[] = {
    {ElementType::Line2, false}, {ElementType::Line3, false}, {ElementType::Line2, true},
    {ElementType::Line3, true},  {ElementType::Tri3, false},  {ElementType::Tri6, false},
    {ElementType::Quad4, false}, {ElementType::Quad8, false}, {ElementType::Quad9, false}};

TEST(SurfaceLoadKernel, FollowerPressureStiffnessMatchesFiniteDifferences) {
  // Central differences of the follower force against the load stiffness, at random deformed
  // positions. The force is a polynomial in u of degree spaceDim - 1 (<= 2; axisymmetric
  // lines: 2, the ring's radius times the normal), so central differences are exact but for
  // round-off: the tolerance is round-off's.
  std::mt19937 rng(7);
  const double p = 3.7, h = 1e-5;
  for (const auto& [t, axisymmetric] : kFollowerFacets) {
    const int D = info(t).dim + 1;
    SurfaceLoadKernel kernel(t, D, -1, axisymmetric);
    const int nd = kernel.numDofs();
    for (int sample = 0; sample < 3; ++sample) {
      const auto facet = deformedFacet(t, rng, 0.4, axisymmetric);
      std::vector<double> f(nd), K(nd * nd), fp(nd), fm(nd), u = facet.u;
      kernel.followerPressure(facet.x.data(), u.data(), p, f.data(), K.data());
      double maxError = 0, maxEntry = test::maxAbs(K);
      for (int j = 0; j < nd; ++j) {
        u[j] = facet.u[j] + h;
        kernel.followerPressure(facet.x.data(), u.data(), p, fp.data(), nullptr);
        u[j] = facet.u[j] - h;
        kernel.followerPressure(facet.x.data(), u.data(), p, fm.data(), nullptr);
        u[j] = facet.u[j];
        for (int i = 0; i < nd; ++i)
          maxError = std::max(maxError, std::abs((fp[i] - fm[i]) / (2 * h) - K[i * nd + j]));
      }
      EXPECT_LT(maxError, 1e-8 * maxEntry) << nameOf(t) << axisymmetric << " sample " << sample;
      if (sample == 0)
        std::printf("follower load stiffness %-6s%s: max |FD - K| / max |K| = %.2e\n",
                    nameOf(t).c_str(), axisymmetric ? " (ring)" : "", maxError / maxEntry);
      // Not symmetric in general.
      double asymmetry = 0;
      for (int i = 0; i < nd; ++i)
        for (int j = 0; j < nd; ++j)
          asymmetry = std::max(asymmetry, std::abs(K[i * nd + j] - K[j * nd + i]));
      EXPECT_GT(asymmetry, 1e-3 * maxEntry) << nameOf(t) << axisymmetric;
    }
  }
}

TEST(SurfaceLoadKernel, FollowerPressureIsTheDeadPressureOnTheDeformedFacet) {
  // At u = 0 it is the dead pressure; at any u, the dead pressure on the moved nodes x + u
  // (on a ring, the moved ring: 2 pi r ds at the current radius).
  std::mt19937 rng(11);
  for (const auto& [t, axisymmetric] : kFollowerFacets) {
    const int D = info(t).dim + 1;
    SurfaceLoadKernel kernel(t, D, -1, axisymmetric);
    const int nd = kernel.numDofs(), n = kernel.numNodes();
    const auto facet = deformedFacet(t, rng, 0.3, axisymmetric);
    std::vector<double> zero(nd, 0.0), f(nd), g(nd);
    kernel.followerPressure(facet.x.data(), zero.data(), 2.0, f.data(), nullptr);
    kernel.pressure(facet.x.data(), 2.0, g.data());
    const double scale = std::max(1.0, test::maxAbs(g));
    for (int k = 0; k < nd; ++k)
      EXPECT_NEAR(f[k], g[k], 1e-13 * scale) << nameOf(t) << axisymmetric;
    std::vector<double> moved = facet.x;
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < D; ++i)
        moved[3 * a + i] += facet.u[a * D + i];
    kernel.followerPressure(facet.x.data(), facet.u.data(), 2.0, f.data(), nullptr);
    kernel.pressure(moved.data(), 2.0, g.data());
    for (int k = 0; k < nd; ++k)
      EXPECT_NEAR(f[k], g[k], 1e-12 * scale) << nameOf(t) << axisymmetric;
  }
}

TEST(SurfaceLoadKernel, RejectsNonFacets) {
  EXPECT_THROW(SurfaceLoadKernel(ElementType::Hex8, 3), std::invalid_argument);
  EXPECT_THROW(SurfaceLoadKernel(ElementType::Quad4, 2), std::invalid_argument);
  EXPECT_THROW(SurfaceLoadKernel(ElementType::Line2, 3), std::invalid_argument);
  EXPECT_THROW(SurfaceLoadKernel(ElementType::Point1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace contactlab
