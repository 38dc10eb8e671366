// Mortar integrals D and M of one slave facet against master facets: identities that hold to
// round-off (matching facets give the mass matrix, the patch property sum_l M_jl = sum_k D_jk,
// exact transfer of linear fields between coplanar facets, biorthogonality of the dual basis)
// and coverage of known areas.
#include "core/contact/MortarClipping.hpp"
#include "core/contact/MortarIntegration.hpp"
#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/QuadratureRule.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <stdexcept>
#include <vector>

namespace contactlab {
namespace {

using Vec3 = std::array<double, 3>;
using Map = std::function<Vec3(double, double)>;

const double kPi = std::acos(-1.0);
const std::vector<MultiplierBasis> kBases = {MultiplierBasis::Standard, MultiplierBasis::Dual};

bool isLine(ElementType t) {
  return t == ElementType::Line2 || t == ElementType::Line3;
}

// A facet whose node a sits at map(reference coordinates of a).
Facet makeFacet(ElementType t, const Map& map, std::int64_t tag = 0) {
  const ReferenceElement& ref = ReferenceElement::get(t);
  Facet f{t, {}, tag};
  for (int a = 0; a < ref.numNodes(); ++a) {
    const double* xi = &ref.nodeCoordinates()[a * ref.dim()];
    const Vec3 x = map(xi[0], ref.dim() > 1 ? xi[1] : 0.0);
    f.coords.insert(f.coords.end(), x.begin(), x.end());
  }
  return f;
}

// The same surface traversed the other way round: a master facing the slave.
Facet makeMaster(ElementType t, const Map& map, std::int64_t tag = 0) {
  if (isLine(t))
    return makeFacet(
        t, [&](double u, double v) { return map(-u, v); }, tag);
  return makeFacet(
      t, [&](double u, double v) { return map(v, u); }, tag);
}

// Rotation by `angle` about the unit `axis` through `centre`.
Vec3 rotate(const Vec3& p, const Vec3& axis, double angle, const Vec3& centre = {0, 0, 0}) {
  const Vec3 d{p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]};
  const double c = std::cos(angle), s = std::sin(angle);
  const double ad = axis[0] * d[0] + axis[1] * d[1] + axis[2] * d[2];
  const Vec3 cr{axis[1] * d[2] - axis[2] * d[1], axis[2] * d[0] - axis[0] * d[2],
                axis[0] * d[1] - axis[1] * d[0]};
  Vec3 r;
  for (int i = 0; i < 3; ++i)
    r[i] = centre[i] + c * d[i] + s * cr[i] + (1 - c) * ad * axis[i];
  return r;
}

// A generic rigid motion, so that the 3D cases are aligned with no coordinate axis.
Vec3 place(const Vec3& p) {
  const double k = 1 / std::sqrt(14.0);
  const Vec3 r = rotate(p, {k, 2 * k, 3 * k}, 0.4);
  return {r[0] + 0.3, r[1] - 0.2, r[2] + 0.7};
}

// The slave facets of the tests: the unit square [0, 1]^2 (quads), the triangle (0,0), (1,0),
// (0,1) (triangles), the segment [0, 1] (lines), placed in space by `place` in 3D.
Map unitSlave(ElementType t) {
  if (isLine(t)) return [](double u, double) { return Vec3{0.5 + 0.5 * u, 0.0, 0.0}; };
  if (t == ElementType::Tri3 || t == ElementType::Tri6)
    return [](double u, double v) { return place({u, v, 0.0}); };
  return [](double u, double v) { return place({0.5 + 0.5 * u, 0.5 + 0.5 * v, 0.0}); };
}

// A skewed segment or parallelogram (triangle): affine, so every integrand is a polynomial.
Map skewedSlave(ElementType t) {
  return [t](double u, double v) {
    if (isLine(t)) return Vec3{0.2 + 0.65 * u, 0.3 - 0.1 * u, 0.0};
    return place({0.5 * u + 0.2 * v, 0.1 * u + 0.7 * v, 0.0});
  };
}

// Geometric unit normal at each node.
std::vector<Vec3> nodeNormals(const Facet& f) {
  const ReferenceElement& ref = ReferenceElement::get(f.type);
  std::vector<Vec3> normals(ref.numNodes());
  std::vector<double> dN(ref.numNodes() * ref.dim());
  for (int a = 0; a < ref.numNodes(); ++a) {
    ref.shapeDerivatives(&ref.nodeCoordinates()[a * ref.dim()], dN.data());
    facetGeometry(ref.dim() + 1, ref.numNodes(), f.coords.data(), dN.data(), normals[a].data());
  }
  return normals;
}

// Consistent mass matrix int N_j N_k dA and shape integrals int N_j dA of a whole facet, by a
// rule far above the integrands' degree.
struct FacetMatrices {
  std::vector<double> mass, lumped;
  double area = 0;
};

FacetMatrices facetMatrices(const Facet& f) {
  const ReferenceElement& ref = ReferenceElement::get(f.type);
  const int n = ref.numNodes();
  const QuadratureRule& rule = quadratureRule(f.type, 14);
  FacetMatrices out{std::vector<double>(n * n, 0.0), std::vector<double>(n, 0.0)};
  std::vector<double> N(n), dN(n * ref.dim());
  for (int q = 0; q < rule.size(); ++q) {
    ref.shape(&rule.points[q * ref.dim()], N.data());
    ref.shapeDerivatives(&rule.points[q * ref.dim()], dN.data());
    double normal[3];
    const double dA =
        rule.weights[q] * facetGeometry(ref.dim() + 1, n, f.coords.data(), dN.data(), normal);
    out.area += dA;
    for (int j = 0; j < n; ++j) {
      out.lumped[j] += N[j] * dA;
      for (int k = 0; k < n; ++k)
        out.mass[j * n + k] += N[j] * N[k] * dA;
    }
  }
  return out;
}

std::vector<const Facet*> pointers(const std::vector<Facet>& facets) {
  std::vector<const Facet*> p;
  for (const Facet& f : facets)
    p.push_back(&f);
  return p;
}

// sum_k D_jk f(x_k) and sum_m sum_l M_jl f(x_l) for every j: equal for the constant field
// (the patch property) and for linear fields between coplanar facets.
void transferred(const Facet& slave, const std::vector<Facet>& masters, const MortarIntegrals& r,
                 const std::function<double(const double*)>& f, std::vector<double>& fromD,
                 std::vector<double>& fromM) {
  const int ns = info(slave.type).nodes;
  fromD.assign(ns, 0.0);
  fromM.assign(ns, 0.0);
  for (int j = 0; j < ns; ++j)
    for (int k = 0; k < ns; ++k)
      fromD[j] += r.D[j * ns + k] * f(&slave.coords[3 * k]);
  for (const MortarMaster& mm : r.masters) {
    const Facet& m = masters[mm.facet];
    const int nm = info(m.type).nodes;
    for (int j = 0; j < ns; ++j)
      for (int l = 0; l < nm; ++l)
        fromM[j] += mm.M[j * nm + l] * f(&m.coords[3 * l]);
  }
}

void expectTransfer(const Facet& slave, const std::vector<Facet>& masters, const MortarIntegrals& r,
                    const std::function<double(const double*)>& f, double tolerance) {
  std::vector<double> fromD, fromM;
  transferred(slave, masters, r, f, fromD, fromM);
  for (std::size_t j = 0; j < fromD.size(); ++j)
    EXPECT_NEAR(fromM[j], fromD[j], tolerance) << "row " << j;
}

double constantField(const double*) {
  return 1.0;
}

double linearField(const double* x) {
  return 0.7 + 1.3 * x[0] - 2.1 * x[1] + 0.9 * x[2];
}

// An n x n grid of master quads (or lines, n segments) over [lo, hi]^2, rotated by `angle`
// about the slave's normal through the slave's centre (0.5, 0.5), offset by h along the
// normal, then placed like the slave.
std::vector<Facet> masterGrid(ElementType t, int n, double lo, double hi, double angle,
                              double h = 0.0, const Vec3& tiltAxis = {1, 0, 0}, double tilt = 0.0) {
  std::vector<Facet> masters;
  const double size = (hi - lo) / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < (isLine(t) ? 1 : n); ++j) {
      const Map map = [=](double u, double v) {
        Vec3 p{lo + (i + 0.5 * (u + 1)) * size, lo + (j + 0.5 * (v + 1)) * size, h};
        if (isLine(t)) return Vec3{p[0], h, 0.0};
        p = rotate(p, {0, 0, 1}, angle, {0.5, 0.5, 0});
        p = rotate(p, tiltAxis, tilt, {0.5, 0.5, 0});
        return place(p);
      };
      masters.push_back(makeMaster(t, map, static_cast<std::int64_t>(masters.size())));
    }
  return masters;
}

// ---- Plane polygons ----

TEST(MortarClipping, ClipsConvexPolygons) {
  const Polygon2 square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const Polygon2 shifted{{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}};
  EXPECT_NEAR(signedArea(clipConvex(square, shifted, 1e-12)), 0.25, 1e-16);
  // A coincident clip polygon keeps the subject, without near-duplicate vertices.
  EXPECT_EQ(clipConvex(square, square, 1e-12).size(), 4u);
  EXPECT_TRUE(clipConvex(square, {{2, 0}, {3, 0}, {3, 1}}, 1e-12).empty());
  // A diamond inside the square's corners: an octagon.
  const Polygon2 diamond{{0.5, -0.2}, {1.2, 0.5}, {0.5, 1.2}, {-0.2, 0.5}};
  const Polygon2 octagon = clipConvex(square, diamond, 1e-12);
  EXPECT_EQ(octagon.size(), 8u);
  EXPECT_NEAR(signedArea(octagon), 1 - 4 * 0.5 * 0.3 * 0.3, 1e-15);
}

TEST(MortarClipping, SplitsANonConvexQuadAtItsReflexVertex) {
  // Clockwise dart with its reflex vertex at (0.5, 0.4).
  const Polygon2 dart{{0, 0}, {0.5, 1}, {1, 0}, {0.5, 0.4}};
  const std::vector<Polygon2> pieces = convexPieces(dart);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_NEAR(signedArea(pieces[0]) + signedArea(pieces[1]), -signedArea(dart), 1e-15);
  for (const Polygon2& piece : pieces)
    EXPECT_GT(signedArea(piece), 0.0);
  EXPECT_EQ(convexPieces({{0, 0}, {1, 0}, {1, 1}, {0, 1}}).size(), 1u);
  EXPECT_THROW(convexPieces({{0, 0}, {1, 1}, {1, 0}, {0, 1}}), std::invalid_argument);  // bow tie
}

// ---- 1. Matching facets ----

// D = T M_e, T the multiplier basis transform (the identity but on tri6/quad8).
TEST(MortarIntegration, IdenticalFacetsGiveTheConsistentMassMatrix) {
  for (ElementType t :
       {ElementType::Line2, ElementType::Line3, ElementType::Tri3, ElementType::Tri6,
        ElementType::Quad4, ElementType::Quad8, ElementType::Quad9}) {
    const Map map = skewedSlave(t);
    const Facet slave = makeFacet(t, map);
    const std::vector<Facet> masters = {makeMaster(t, map)};
    const MortarIntegrals r =
        integrateMortar(slave, nodeNormals(slave), pointers(masters), MultiplierBasis::Standard);
    const FacetMatrices exact = facetMatrices(slave);
    const std::vector<double> T = multiplierBasisTransform(t);
    const int n = info(t).nodes;
    ASSERT_EQ(r.masters.size(), 1u);
    EXPECT_NEAR(r.area, exact.area, 1e-14);
    EXPECT_NEAR(r.coveredArea, exact.area, 1e-14) << info(t).name;
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        double transformed = 0.0;
        for (int m = 0; m < n; ++m)
          transformed += T[j * n + m] * exact.mass[m * n + k];
        EXPECT_NEAR(r.D[j * n + k], transformed, 1e-15) << info(t).name;
        // The master node at slave node k's position.
        int l = 0;
        while (std::hypot(masters[0].coords[3 * l] - slave.coords[3 * k],
                          masters[0].coords[3 * l + 1] - slave.coords[3 * k + 1],
                          masters[0].coords[3 * l + 2] - slave.coords[3 * k + 2]) > 1e-12)
          ++l;
        EXPECT_NEAR(r.masters[0].M[j * n + l], r.D[j * n + k], 1e-15) << info(t).name;
      }
  }
}

// ---- 2. and 3. Patch property and linear fields on non-matching facets ----

struct PatchCase {
  ElementType slave, master;
  int grid;
  double lo, hi, angle;
};

const std::vector<PatchCase> kPatchCases = {
    {ElementType::Quad4, ElementType::Quad4, 3, -0.3, 1.3, 7 * kPi / 180},
    {ElementType::Quad4, ElementType::Quad4, 4, -0.3, 1.3, 7 * kPi / 180},
    {ElementType::Tri3, ElementType::Quad4, 3, -0.3, 1.3, 7 * kPi / 180},
    {ElementType::Quad9, ElementType::Quad4, 4, -0.3, 1.3, 7 * kPi / 180},
    {ElementType::Tri6, ElementType::Quad4, 3, -0.3, 1.3, 7 * kPi / 180},
    {ElementType::Quad8, ElementType::Tri3, 4, -0.3, 1.3, 7 * kPi / 180},
    {ElementType::Quad4, ElementType::Tri3, 3, -0.3, 1.3, 7 * kPi / 180},
    {ElementType::Line2, ElementType::Line2, 3, -0.2, 1.1, 0},
    {ElementType::Line3, ElementType::Line3, 3, -0.2, 1.1, 0},
    {ElementType::Line3, ElementType::Line2, 3, -0.2, 1.1, 0}};

// Tri3 masters: each grid quad split into two triangles.
std::vector<Facet> patchMasters(const PatchCase& c, double h = 0.0) {
  if (c.master != ElementType::Tri3) return masterGrid(c.master, c.grid, c.lo, c.hi, c.angle, h);
  const int halves[2][3] = {{0, 1, 2}, {0, 2, 3}};
  std::vector<Facet> triangles;
  for (const Facet& q : masterGrid(ElementType::Quad4, c.grid, c.lo, c.hi, c.angle, h))
    for (const auto& nodes : halves) {
      Facet t{ElementType::Tri3, {}, q.tag};
      for (int a : nodes)
        t.coords.insert(t.coords.end(), &q.coords[3 * a], &q.coords[3 * a] + 3);
      triangles.push_back(t);
    }
  return triangles;
}

// `check` on every patch case's slave, masters and integrals, in each basis.
void forEachPatchCase(const std::function<void(const Facet&, const std::vector<Facet>&,
                                               const MortarIntegrals&)>& check) {
  for (const PatchCase& c : kPatchCases)
    for (MultiplierBasis basis : kBases) {
      const Facet slave = makeFacet(c.slave, unitSlave(c.slave));
      const std::vector<Facet> masters = patchMasters(c);
      const MortarIntegrals r =
          integrateMortar(slave, nodeNormals(slave), pointers(masters), basis);
      SCOPED_TRACE(std::string(info(c.slave).name) + " on " + info(c.master).name);
      check(slave, masters, r);
    }
}

TEST(MortarIntegration, PatchPropertyOnNonMatchingMasters) {
  forEachPatchCase(
      [](const Facet& slave, const std::vector<Facet>& masters, const MortarIntegrals& r) {
        EXPECT_GE(r.masters.size(), 3u);
        EXPECT_NEAR(r.coveredArea, r.area, 1e-13 * r.area);
        expectTransfer(slave, masters, r, constantField, 1e-13 * r.area);
      });
}

TEST(MortarIntegration, LinearFieldsTransferExactlyBetweenCoplanarFacets) {
  forEachPatchCase(
      [](const Facet& slave, const std::vector<Facet>& masters, const MortarIntegrals& r) {
        expectTransfer(slave, masters, r, linearField, 1e-12 * r.area);
      });
}

// ---- 4. Dual basis ----

// Biorthogonal to the transformed functions T N (T the identity but on tri6/quad8):
// int Phi_j (T N)_k = (D T^T)_jk = delta_jk int (T N)_j.
TEST(MortarIntegration, DualBasisIsBiorthogonal) {
  for (ElementType t :
       {ElementType::Line2, ElementType::Line3, ElementType::Tri3, ElementType::Tri6,
        ElementType::Quad4, ElementType::Quad8, ElementType::Quad9}) {
    const Map map = skewedSlave(t);
    const Facet slave = makeFacet(t, map);
    const std::vector<Facet> masters = {makeMaster(t, map)};
    const MortarIntegrals r =
        integrateMortar(slave, nodeNormals(slave), pointers(masters), MultiplierBasis::Dual);
    const FacetMatrices exact = facetMatrices(slave);
    const std::vector<double> B = dualBasisCoefficients(slave);
    const std::vector<double> T = multiplierBasisTransform(t);
    const int n = info(t).nodes;
    for (int j = 0; j < n; ++j) {
      double integral = 0.0, transformed = 0.0;  // int Phi_j dA, int (T N)_j dA
      for (int k = 0; k < n; ++k) {
        integral += B[j * n + k] * exact.lumped[k];
        transformed += T[j * n + k] * exact.lumped[k];
      }
      EXPECT_GT(transformed, 0.0) << info(t).name;
      EXPECT_NEAR(integral, transformed, 1e-14) << info(t).name;
      for (int k = 0; k < n; ++k) {
        double against = 0.0;
        for (int m = 0; m < n; ++m)
          against += r.D[j * n + m] * T[k * n + m];
        EXPECT_NEAR(against, j == k ? transformed : 0.0, 1e-14) << info(t).name;
      }
    }
  }
}

// tri6 and quad8 corner functions integrate to zero and to -A/12: with Phi = N their weighted
// gaps would vanish or change sign. The transformed bases give every node a positive weight
// sum_k D_jk = int Phi_j: tri6 2A/15 at corners and A/5 at mid-edges, quad8 A/20 and A/5
// (alpha = 1/5), in both bases.
TEST(MortarIntegration, QuadraticSlaveFacetsGetPositiveWeights) {
  for (ElementType t : {ElementType::Tri6, ElementType::Quad8}) {
    const Facet slave = makeFacet(t, unitSlave(t));
    const FacetMatrices exact = facetMatrices(slave);
    const int n = info(t).nodes, corners = n / 2;
    const double cornerWeight = (t == ElementType::Tri6 ? 2.0 / 15.0 : 1.0 / 20.0) * exact.area;
    EXPECT_NEAR(exact.lumped[0], t == ElementType::Tri6 ? 0.0 : -exact.area / 12, 1e-14);
    for (MultiplierBasis basis : kBases) {
      const MortarIntegrals r = integrateMortar(slave, nodeNormals(slave), {&slave}, basis);
      SCOPED_TRACE(info(t).name);
      for (int j = 0; j < n; ++j) {
        double weight = 0.0;
        for (int k = 0; k < n; ++k)
          weight += r.D[j * n + k];
        EXPECT_NEAR(weight, j < corners ? cornerWeight : exact.area / 5, 1e-14);
      }
    }
  }
}

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

// VERIFICATION.md V3's rotated case: the hex faces of a 5 x 5 block top against a 3 x 3 block
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
