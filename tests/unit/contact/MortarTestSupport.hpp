#pragma once
// Helpers shared by the mortar-integral tests: facets built from a map of their reference
// coordinates (a slave and the master on the same surface facing it), rigid motions, nodal
// normals, a facet's exact mass matrix, the transfer of a field through D and M, grids of
// masters, the patch cases and a slave against its matching master.
#include "core/contact/MortarIntegration.hpp"
#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/QuadratureRule.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace contactlab::test {

using Vec3 = std::array<double, 3>;
using Map = std::function<Vec3(double, double)>;

inline const double kPi = std::acos(-1.0);
inline const std::vector<MultiplierBasis> kBases = {MultiplierBasis::Standard,
                                                    MultiplierBasis::Dual};

inline bool isLine(ElementType t) {
  return t == ElementType::Line2 || t == ElementType::Line3;
}

// A facet whose node a sits at map(reference coordinates of a).
inline Facet makeFacet(ElementType t, const Map& map, std::int64_t tag = 0) {
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
inline Facet makeMaster(ElementType t, const Map& map, std::int64_t tag = 0) {
  if (isLine(t))
    return makeFacet(
        t, [&](double u, double v) { return map(-u, v); }, tag);
  return makeFacet(
      t, [&](double u, double v) { return map(v, u); }, tag);
}

// Rotation by `angle` about the unit `axis` through `centre`.
inline Vec3 rotate(const Vec3& p, const Vec3& axis, double angle, const Vec3& centre = {0, 0, 0}) {
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
inline Vec3 place(const Vec3& p) {
  const double k = 1 / std::sqrt(14.0);
  const Vec3 r = rotate(p, {k, 2 * k, 3 * k}, 0.4);
  return {r[0] + 0.3, r[1] - 0.2, r[2] + 0.7};
}

// The slave facets of the tests: the unit square [0, 1]^2 (quads), the triangle (0,0), (1,0),
// (0,1) (triangles), the segment [0, 1] (lines), placed in space by `place` in 3D.
inline Map unitSlave(ElementType t) {
  if (isLine(t)) return [](double u, double) { return Vec3{0.5 + 0.5 * u, 0.0, 0.0}; };
  if (t == ElementType::Tri3 || t == ElementType::Tri6)
    return [](double u, double v) { return place({u, v, 0.0}); };
  return [](double u, double v) { return place({0.5 + 0.5 * u, 0.5 + 0.5 * v, 0.0}); };
}

// A skewed segment or parallelogram (triangle): affine, so every integrand is a polynomial.
inline Map skewedSlave(ElementType t) {
  return [t](double u, double v) {
    if (isLine(t)) return Vec3{0.2 + 0.65 * u, 0.3 - 0.1 * u, 0.0};
    return place({0.5 * u + 0.2 * v, 0.1 * u + 0.7 * v, 0.0});
  };
}

// Geometric unit normal at each node.
inline std::vector<Vec3> nodeNormals(const Facet& f) {
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

inline FacetMatrices facetMatrices(const Facet& f) {
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

inline std::vector<const Facet*> pointers(const std::vector<Facet>& facets) {
  std::vector<const Facet*> p;
  for (const Facet& f : facets)
    p.push_back(&f);
  return p;
}

// sum_k D_jk f(x_k) and sum_m sum_l M_jl f(x_l) for every j: equal for the constant field
// (the patch property) and for linear fields between coplanar facets.
inline void transferred(const Facet& slave, const std::vector<Facet>& masters,
                        const MortarIntegrals& r, const std::function<double(const double*)>& f,
                        std::vector<double>& fromD, std::vector<double>& fromM) {
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

inline void expectTransfer(const Facet& slave, const std::vector<Facet>& masters,
                           const MortarIntegrals& r, const std::function<double(const double*)>& f,
                           double tolerance) {
  std::vector<double> fromD, fromM;
  transferred(slave, masters, r, f, fromD, fromM);
  for (std::size_t j = 0; j < fromD.size(); ++j)
    EXPECT_NEAR(fromM[j], fromD[j], tolerance) << "row " << j;
}

inline double constantField(const double*) {
  return 1.0;
}

inline double linearField(const double* x) {
  return 0.7 + 1.3 * x[0] - 2.1 * x[1] + 0.9 * x[2];
}

// An n x n grid of master quads (or lines, n segments) over [lo, hi]^2, rotated by `angle`
// about the slave's normal through the slave's centre (0.5, 0.5), offset by h along the
// normal, then placed like the slave.
inline std::vector<Facet> masterGrid(ElementType t, int n, double lo, double hi, double angle,
                                     double h = 0.0, const Vec3& tiltAxis = {1, 0, 0},
                                     double tilt = 0.0) {
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

struct PatchCase {
  ElementType slave, master;
  int grid;
  double lo, hi, angle;
};

inline const std::vector<PatchCase> kPatchCases = {
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
inline std::vector<Facet> patchMasters(const PatchCase& c, double h = 0.0) {
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
inline void forEachPatchCase(const std::function<void(const Facet&, const std::vector<Facet>&,
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

// Every facet type the mortar integrals take.
inline const ElementType kFacetTypes[] = {
    ElementType::Line2, ElementType::Line3, ElementType::Tri3, ElementType::Tri6,
    ElementType::Quad4, ElementType::Quad8, ElementType::Quad9};

// A skewed slave facet against the one master on the same surface, with their integrals.
struct MatchingFacets {
  Facet slave;
  std::vector<Facet> masters;
  MortarIntegrals integrals;
  FacetMatrices exact;    // the slave's own mass matrix and shape integrals
  std::vector<double> T;  // the multiplier basis transform of the slave's type
  int n;                  // nodes per facet
};

inline MatchingFacets matchingFacets(ElementType t, MultiplierBasis basis) {
  const Map map = skewedSlave(t);
  MatchingFacets m{makeFacet(t, map),           {makeMaster(t, map)}, {}, {},
                   multiplierBasisTransform(t), info(t).nodes};
  m.integrals = integrateMortar(m.slave, nodeNormals(m.slave), pointers(m.masters), basis);
  m.exact = facetMatrices(m.slave);
  return m;
}

}  // namespace contactlab::test
