#include "tests/unit/fem/FemTestSupport.hpp"

#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/QuadratureRule.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <optional>
#include <string>

namespace contactlab {
namespace {

using test::nameOf;
const double kPi = std::acos(-1.0);

// x = A xi + c applied to the reference nodes.
std::vector<double> affineNodes(ElementType t, const double (&A)[3][3], const double* c) {
  const auto& ref = ReferenceElement::get(t);
  const int d = ref.dim();
  std::vector<double> x(3 * ref.numNodes(), 0.0);
  for (int a = 0; a < ref.numNodes(); ++a)
    for (int i = 0; i < d; ++i) {
      x[3 * a + i] = c[i];
      for (int j = 0; j < d; ++j)
        x[3 * a + i] += A[i][j] * ref.nodeCoordinates()[a * d + j];
    }
  return x;
}

// The InvalidElementError that physicalGradients throws at the first point of t's degree-2 rule
// on the nodes A xi + c; none (and a test failure) when it does not throw.
std::optional<InvalidElementError> gradientsError(ElementType t, const double (&A)[3][3],
                                                  const double* c) {
  const auto& ref = ReferenceElement::get(t);
  const auto x = affineNodes(t, A, c);
  const auto& rule = quadratureRule(t, 2);
  std::vector<double> dNdxi(ref.numNodes() * ref.dim()), dNdx(dNdxi.size());
  ref.shapeDerivatives(rule.points.data(), dNdxi.data());
  try {
    physicalGradients(ref.dim(), ref.numNodes(), x.data(), dNdxi.data(), dNdx.data());
  } catch (const InvalidElementError& e) {
    return e;
  }
  ADD_FAILURE() << nameOf(t) << " did not throw";
  return std::nullopt;
}

TEST(IsoparametricMap, AffineMapGivesExactJacobianAndGradients) {
  const double A[3][3] = {{2.0, 0.5, 0.1}, {-0.3, 1.5, 0.2}, {0.4, -0.2, 0.8}};
  const double c[3] = {1, 2, 3};
  std::mt19937 rng(4);
  for (ElementType t : test::solidTypes()) {
    const auto& ref = ReferenceElement::get(t);
    const int n = ref.numNodes(), d = ref.dim();
    const auto x = affineNodes(t, A, c);
    double Ad[9], Ainv[9];
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j)
        Ad[i * d + j] = A[i][j];
    const double detA = invert(d, Ad, Ainv);
    std::vector<double> dNdxi(n * d), dNdx(n * d);
    for (int trial = 0; trial < 4; ++trial) {
      const auto xi = test::randomPoint(t, rng);
      ref.shapeDerivatives(xi.data(), dNdxi.data());
      double J[9];
      jacobian(d, n, x.data(), dNdxi.data(), J);
      for (int k = 0; k < d * d; ++k)
        EXPECT_NEAR(J[k], Ad[k], 1e-13) << nameOf(t);
      EXPECT_NEAR(physicalGradients(d, n, x.data(), dNdxi.data(), dNdx.data()), detA, 1e-13)
          << nameOf(t);
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < d; ++i) {
          double expected = 0;
          for (int j = 0; j < d; ++j)
            expected += dNdxi[a * d + j] * Ainv[j * d + i];
          EXPECT_NEAR(dNdx[a * d + i], expected, 1e-13) << nameOf(t);
        }
    }
  }
}

TEST(IsoparametricMap, InvertedElementThrows) {
  const double mirror[3][3] = {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const double c[3] = {0, 0, 0};
  for (ElementType t : test::solidTypes()) {
    const auto e = gradientsError(t, mirror, c);
    if (!e) continue;
    EXPECT_EQ(e->kind(), InvalidElementError::Kind::Inverted);
    EXPECT_NE(std::string(e->what()).find("inverted"), std::string::npos) << e->what();
    const std::string labelled = e->withLabel("element 42 (gmsh tag 1234) of block 'body'").what();
    EXPECT_EQ(labelled.rfind("element 42 (gmsh tag 1234) of block 'body' is inverted: det J = ", 0),
              0u)
        << labelled;
    EXPECT_NE(labelled.find("at a quadrature point"), std::string::npos);
  }
}

TEST(IsoparametricMap, CollapsedElementThrows) {
  // Last coordinate squashed to zero: the element is flat.
  const double flat[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 0}};
  const double flat2d[3][3] = {{1, 0.5, 0}, {2, 1, 0}, {0, 0, 1}};  // rank-1 in 2D
  const double c[3] = {0, 0, 0};
  for (ElementType t : test::solidTypes()) {
    const auto e = gradientsError(t, info(t).dim == 3 ? flat : flat2d, c);
    if (!e) continue;
    EXPECT_EQ(e->kind(), InvalidElementError::Kind::Degenerate);
    EXPECT_NE(std::string(e->what()).find("degenerate"), std::string::npos) << e->what();
  }
  // All nodes at one point.
  std::vector<double> x(3 * 8, 1.0), dNdxi(24), dNdx(24);
  const double xi[3] = {0.1, 0.2, 0.3};
  ReferenceElement::get(ElementType::Hex8).shapeDerivatives(xi, dNdxi.data());
  EXPECT_THROW(physicalGradients(3, 8, x.data(), dNdxi.data(), dNdx.data()), InvalidElementError);
}

TEST(IsoparametricMap, LargeButValidElementsPass) {
  // Scale invariance: a 1e-6 sized, 1000:1 stretched hex is fine.
  const double A[3][3] = {{1e-3, 0, 0}, {0, 1e-6, 0}, {0, 0, 1e-6}};
  const double c[3] = {5, 5, 5};
  const auto x = affineNodes(ElementType::Hex8, A, c);
  std::vector<double> dNdxi(24), dNdx(24);
  const double xi[3] = {0.1, 0.2, 0.3};
  ReferenceElement::get(ElementType::Hex8).shapeDerivatives(xi, dNdxi.data());
  EXPECT_NEAR(physicalGradients(3, 8, x.data(), dNdxi.data(), dNdx.data()), 1e-15, 1e-25);
}

// Facet geometry at xi, returning dA and the normal.
double facetAt(ElementType t, const std::vector<double>& x, const double* xi, double* n) {
  const auto& ref = ReferenceElement::get(t);
  std::vector<double> dNdxi(ref.numNodes() * ref.dim());
  ref.shapeDerivatives(xi, dNdxi.data());
  return facetGeometry(ref.dim() + 1, ref.numNodes(), x.data(), dNdxi.data(), n);
}

double facetArea(ElementType t, const std::vector<double>& x, int degree = 12) {
  const auto& rule = quadratureRule(t, degree);
  double area = 0, n[3];
  for (int q = 0; q < rule.size(); ++q)
    area += rule.weights[q] * facetAt(t, x, &rule.points[q * rule.dim], n);
  return area;
}

TEST(IsoparametricMap, StraightLineFacet) {
  // From (1,0) to (1,2): counter-clockwise on the right side of a body left of x = 1, so the
  // normal is +x.
  const std::vector<double> x = {1, 0, 0, 1, 2, 0};
  double n[3];
  const double xi = 0.3;
  EXPECT_NEAR(facetAt(ElementType::Line2, x, &xi, n), 1.0, 1e-15);
  EXPECT_NEAR(n[0], 1.0, 1e-15);
  EXPECT_NEAR(n[1], 0.0, 1e-15);
  EXPECT_NEAR(facetArea(ElementType::Line2, x), 2.0, 1e-14);
  // Line3 with the mid node in the middle: same.
  const std::vector<double> x3 = {1, 0, 0, 1, 2, 0, 1, 1, 0};
  EXPECT_NEAR(facetArea(ElementType::Line3, x3), 2.0, 1e-14);
}

TEST(IsoparametricMap, CurvedLine3Arc) {
  // Quarter circle of radius R, counter-clockwise from angle 0 to 90 degrees, mid node on the
  // arc: the normal is radial (outward) at the mid node and the length close to pi R / 2.
  const double R = 2.0, s = R / std::sqrt(2.0);
  const std::vector<double> x = {R, 0, 0, 0, R, 0, s, s, 0};
  double n[3];
  const double mid = 0.0;
  facetAt(ElementType::Line3, x, &mid, n);
  EXPECT_NEAR(n[0], 1 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(n[1], 1 / std::sqrt(2.0), 1e-15);
  // Normal radial at the ends too, up to the parabola's error.
  const double end = -1.0;
  facetAt(ElementType::Line3, x, &end, n);
  EXPECT_GT(n[0], 0.99);
  // Length of the interpolating parabola, by a fine midpoint sum of |x(xi_k+1) - x(xi_k)|.
  const auto& ref = ReferenceElement::get(ElementType::Line3);
  double length = 0, prev[2] = {R, 0};
  for (int k = 1; k <= 20000; ++k) {
    const double xi = -1 + 2.0 * k / 20000;
    double N[3];
    ref.shape(&xi, N);
    const double p[2] = {N[0] * x[0] + N[1] * x[3] + N[2] * x[6],
                         N[0] * x[1] + N[1] * x[4] + N[2] * x[7]};
    length += std::hypot(p[0] - prev[0], p[1] - prev[1]);
    prev[0] = p[0], prev[1] = p[1];
  }
  EXPECT_NEAR(facetArea(ElementType::Line3, x, 30), length, 1e-8);
  EXPECT_NEAR(length, kPi * R / 2, 0.02 * R);
}

// Rotation about the axis (1, 1, 1)/sqrt(3) by 40 degrees.
void rotate(const double* p, double* out) {
  const double k[3] = {1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
  const double th = 40 * kPi / 180, c = std::cos(th), s = std::sin(th);
  const double kp = k[0] * p[0] + k[1] * p[1] + k[2] * p[2];
  const double kxp[3] = {k[1] * p[2] - k[2] * p[1], k[2] * p[0] - k[0] * p[2],
                         k[0] * p[1] - k[1] * p[0]};
  for (int i = 0; i < 3; ++i)
    out[i] = p[i] * c + kxp[i] * s + k[i] * kp * (1 - c);
}

TEST(IsoparametricMap, TiltedFlatSurfaceFacets) {
  // Rectangle 3 x 2 (and its triangle halves) in the xy plane, rotated: the normal is the
  // rotated +z (right-hand rule on 0-1-2), the area 6 (3 for the triangles).
  const double ez[3] = {0, 0, 1};
  double nExpected[3];
  rotate(ez, nExpected);
  for (ElementType t : {ElementType::Tri3, ElementType::Tri6, ElementType::Quad4,
                        ElementType::Quad8, ElementType::Quad9}) {
    const auto& ref = ReferenceElement::get(t);
    std::vector<double> x(3 * ref.numNodes());
    for (int a = 0; a < ref.numNodes(); ++a) {
      const double* xi = &ref.nodeCoordinates()[2 * a];
      // Tensor cells [-1,1]^2 -> [0,3]x[0,2]; triangles: unit simplex -> legs 3 and 2.
      double p[3] = {test::isSimplex(t) ? 3 * xi[0] : 1.5 * (xi[0] + 1),
                     test::isSimplex(t) ? 2 * xi[1] : xi[1] + 1, 0};
      rotate(p, &x[3 * a]);
    }
    double n[3];
    const double xi[2] = {0.2, 0.3};
    facetAt(t, x, xi, n);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(n[i], nExpected[i], 1e-14) << nameOf(t);
    EXPECT_NEAR(facetArea(t, x, 4), test::isSimplex(t) ? 3.0 : 6.0, 1e-13) << nameOf(t);
  }
}

TEST(IsoparametricMap, DegenerateFacetThrows) {
  const std::vector<double> line = {1, 1, 0, 1, 1, 0};
  const std::vector<double> quad = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0};  // all on a line
  double n[3];
  const double xi[2] = {0.1, 0.1};
  EXPECT_THROW(facetAt(ElementType::Line2, line, xi, n), InvalidElementError);
  try {
    facetAt(ElementType::Quad4, quad, xi, n);
    ADD_FAILURE() << "no throw";
  } catch (const InvalidElementError& e) {
    EXPECT_NE(std::string(e.what()).find("degenerate"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace contactlab
