#include "core/contact/MortarIntegration.hpp"

#include "core/contact/MortarClipping.hpp"
#include "core/contact/MortarMasterSelection.hpp"
#include "core/contact/SurfaceFrames.hpp"
#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/QuadratureRule.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace contactlab {
namespace {

constexpr int kMaxNodes = 9;
constexpr int kMaxNewton = 30;
// Clip cells below this fraction of the slave's area are round-off slivers of touching edges.
constexpr double kSliver = 1e-12;

double dot3(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Stopping rule of the Newton projections, on the step in reference coordinates: below 1e-14 the
// current point is kept as it is (no re-evaluation: an affine map converges in two evaluations);
// steps that stop shrinking below 1e-9 are round-off (coordinates large against the facet size).
bool newtonConverged(double step, double previous) {
  return step < 1e-14 || (step < 1e-9 && step > 0.25 * previous);
}

// z component of a x b for in-plane vectors.
double cross2(const double* a, const double* b) {
  return a[0] * b[1] - a[1] * b[0];
}

// The largest distance between two of the facet's nodes.
double facetDiameter(const Facet& f) {
  const std::size_t n = f.coords.size() / 3;
  double d2 = 0;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      double s = 0;
      for (int c = 0; c < 3; ++c)
        s += std::pow(f.coords[3 * a + c] - f.coords[3 * b + c], 2);
      d2 = std::max(d2, s);
    }
  return std::sqrt(d2);
}

std::string describe(const Facet& f) {
  return std::string(info(f.type).name) + " facet (gmsh tag " + std::to_string(f.tag) + ")";
}

// Space dimension of a facet (2 for lines, 3 for surfaces); throws for anything else.
int checkFacet(const Facet& f) {
  const ElementType t = f.type;
  const bool line = t == ElementType::Line2 || t == ElementType::Line3;
  const bool surface = t == ElementType::Tri3 || t == ElementType::Tri6 ||
                       t == ElementType::Quad4 || t == ElementType::Quad8 ||
                       t == ElementType::Quad9;
  if (!line && !surface)
    throw std::invalid_argument("mortar integration: " + describe(f) +
                                " is not a line2, line3, tri3, tri6, quad4, quad8 or quad9 facet");
  if (f.coords.size() != 3 * static_cast<std::size_t>(info(t).nodes))
    throw std::invalid_argument("mortar integration: " + describe(f) + " has " +
                                std::to_string(f.coords.size()) + " coordinates instead of " +
                                std::to_string(3 * info(t).nodes));
  return line ? 2 : 3;
}

// Shape functions, their derivatives, position and tangents of a facet at one reference point.
struct FacetPoint {
  double N[kMaxNodes];
  double dN[2 * kMaxNodes];
  double x[3];
  double a[2][3];  // dx/dxi_j
};

void evaluate(const ReferenceElement& ref, const double* coords, const double* xi, FacetPoint& p) {
  const int n = ref.numNodes(), rd = ref.dim();
  ref.shape(xi, p.N);
  ref.shapeDerivatives(xi, p.dN);
  interpolatePosition(n, coords, p.N, p.x);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      p.a[j][i] = 0.0;
      if (j < rd)
        for (int a = 0; a < n; ++a)
          p.a[j][i] += p.dN[a * rd + j] * coords[3 * a + i];
    }
}

// facetGeometry with the degenerate case reported as bad input, naming the facet.
double areaElement(const Facet& f, int spaceDim, const double* dN, double* normal) {
  try {
    return facetGeometry(spaceDim, info(f.type).nodes, f.coords.data(), dN, normal);
  } catch (const InvalidElementError& e) {
    throw std::invalid_argument("mortar integration: " + describe(f) + " is degenerate (" +
                                e.what() + ")");
  }
}

void facetCentre(ElementType t, double* xi) {
  const bool triangle = t == ElementType::Tri3 || t == ElementType::Tri6;
  xi[0] = xi[1] = triangle ? 1.0 / 3.0 : 0.0;
}

// Total polynomial degree of a facet's shape functions.
int shapeDegree(ElementType t) {
  const int order = info(t).order;
  return (t == ElementType::Quad4 || t == ElementType::Quad8 || t == ElementType::Quad9) ? 2 * order
                                                                                         : order;
}

// int N_j dA over the whole facet, and int N_j N_k dA into `mass` when given. The rule is exact
// on straight and flat facets; a curved quadratic facet's dA is not polynomial, hence the extra
// degrees.
std::vector<double> wholeFacetIntegrals(const Facet& f, int spaceDim, std::vector<double>* mass,
                                        const SurfaceWeight& weight = {},
                                        const FacetField& field = {},
                                        std::vector<double>* fieldIntegrals = nullptr) {
  const ReferenceElement& ref = ReferenceElement::get(f.type);
  const int n = ref.numNodes(), order = info(f.type).order;
  const QuadratureRule& rule = quadratureRule(f.type, 2 * order + (order > 1 ? 6 : 2));
  std::vector<double> lumped(n, 0.0);
  if (mass) mass->assign(static_cast<std::size_t>(n) * n, 0.0);
  if (fieldIntegrals) fieldIntegrals->assign(n, 0.0);
  for (int q = 0; q < rule.size(); ++q) {
    FacetPoint p;
    evaluate(ref, f.coords.data(), &rule.points[q * ref.dim()], p);
    double normal[3];
    const double dA =
        rule.weights[q] * areaElement(f, spaceDim, p.dN, normal) * (weight ? weight(p.x) : 1.0);
    const double value = fieldIntegrals ? field(p.x) : 0.0;
    for (int j = 0; j < n; ++j) {
      lumped[j] += p.N[j] * dA;
      if (fieldIntegrals) (*fieldIntegrals)[j] += p.N[j] * value * dA;
      for (int k = 0; mass && k < n; ++k)
        (*mass)[j * n + k] += p.N[j] * p.N[k] * dA;
    }
  }
  return lumped;
}

// Row-major inverse of a small n x n matrix (a mass matrix) by Gauss-Jordan with partial pivoting.
std::vector<double> inverse(int n, std::vector<double> a) {
  std::vector<double> inv(static_cast<std::size_t>(n) * n, 0.0);
  for (int i = 0; i < n; ++i)
    inv[i * n + i] = 1.0;
  for (int c = 0; c < n; ++c) {
    int pivot = c;
    for (int r = c + 1; r < n; ++r)
      if (std::abs(a[r * n + c]) > std::abs(a[pivot * n + c])) pivot = r;
    for (int k = 0; k < n; ++k) {
      std::swap(a[c * n + k], a[pivot * n + k]);
      std::swap(inv[c * n + k], inv[pivot * n + k]);
    }
    const double d = a[c * n + c];
    for (int k = 0; k < n; ++k)
      a[c * n + k] /= d, inv[c * n + k] /= d;
    for (int r = 0; r < n; ++r) {
      const double f = a[r * n + c];
      if (r == c || f == 0.0) continue;
      for (int k = 0; k < n; ++k)
        a[r * n + k] -= f * a[c * n + k], inv[r * n + k] -= f * inv[c * n + k];
    }
  }
  return inv;
}

// Dual basis coefficients A = diag(d) M^-1 (row major n x n) from the integrals d_j = int N_j
// and M_jk = int N_j N_k over the same region: biorthogonal there, int Phi_j N_k = d_j delta_jk.
// M^-1 is symmetric, so A_jk = d_j (M^-1)_jk.
std::vector<double> dualCoefficients(int n, const std::vector<double>& d,
                                     const std::vector<double>& mass) {
  std::vector<double> A = inverse(n, mass);
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k)
      A[j * n + k] *= d[j];
  return A;
}

// The share of a mid-edge node's function a corner's transformed function gains
// (multiplierBasisTransform, facetBasisTransform): alpha = 1/5, as in Popp's and CalculiX's
// quadratic mortar.
constexpr double kTransformAlpha = 0.2;

bool isIdentity(const std::vector<double>& T, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (T[i * n + j] != (i == j ? 1.0 : 0.0)) return false;
  return true;
}

// Row-major product of two n x n matrices, and A B^T.
std::vector<double> multiply(int n, const std::vector<double>& A, const std::vector<double>& B,
                             bool transposeB = false) {
  std::vector<double> C(static_cast<std::size_t>(n) * n, 0.0);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        C[i * n + j] += A[i * n + k] * (transposeB ? B[j * n + k] : B[k * n + j]);
  return C;
}

// The whole facet's dual basis Phi = A T N from its integrals (wholeFacetIntegrals): the dual of
// the transformed basis T N (T = facetBasisTransform), biorthogonal to T N. Throws
// std::invalid_argument where it does not exist.
std::vector<double> wholeFacetDualBasis(const Facet& slave, const std::vector<double>& lumped,
                                        const std::vector<double>& mass,
                                        const std::vector<double>& T) {
  const int n = static_cast<int>(lumped.size());
  std::vector<double> transformed(n, 0.0);  // int T N
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k)
      transformed[j] += T[j * n + k] * lumped[k];
  const double area = std::accumulate(lumped.begin(), lumped.end(), 0.0);
  for (int j = 0; j < n; ++j)
    if (!(transformed[j] > 1e-12 * area))
      throw std::invalid_argument(
          "mortar integration: the dual multiplier basis does not exist on " + describe(slave) +
          ": the multiplier basis function of its node " + std::to_string(j) +
          " does not integrate to a positive value");
  // int (T N)(T N)^T = T M T^T
  const std::vector<double> transformedMass = multiply(n, multiply(n, T, mass), T, true);
  return multiply(n, dualCoefficients(n, transformed, transformedMass), T);
}

// D += N_S N_S^T dA, M += N_S N_M^T dA (standard basis; the dual one is a transform after).
void accumulate(int ns, const double* NS, int nm, const double* NM, double dA, double* D,
                double* M) {
  for (int j = 0; j < ns; ++j) {
    const double w = NS[j] * dA;
    for (int k = 0; k < ns; ++k)
      D[j * ns + k] += w * NS[k];
    for (int l = 0; l < nm; ++l)
      M[j * nm + l] += w * NM[l];
  }
}

// One integration point of a master's overlap: D, M, the covered area, and the gap and normal
// alignment along the slave's unit normal nS (MortarMasterSelection.hpp).
void accumulate(int ns, const FacetPoint& ps, int nm, const FacetPoint& pm, const double* nS,
                const double* nM, double dA, MasterOverlap& o) {
  accumulate(ns, ps.N, nm, pm.N, dA, o.D.data(), o.integrals.M.data());
  o.area += dA;
  const double g[3] = {pm.x[0] - ps.x[0], pm.x[1] - ps.x[1], pm.x[2] - ps.x[2]};
  o.gapMoment += dA * dot3(g, nS);
  o.alignmentMoment += dA * dot3(nM, nS) / std::sqrt(dot3(nM, nM));
}

MasterOverlap newOverlap(std::size_t m, int ns, int nm) {
  MasterOverlap o;
  o.integrals = MortarMaster{m, std::vector<double>(static_cast<std::size_t>(ns) * nm, 0.0)};
  o.D.assign(static_cast<std::size_t>(ns) * ns, 0.0);
  return o;
}

// ---- 2D: projection along the slave's interpolated nodal normals ----

struct SlaveLine {
  const Facet& facet;
  const ReferenceElement& ref;
  const std::vector<std::array<double, 3>>& normals;

  // Unnormalized normal field sum_j N_j n_j and its derivative: the zero of a cross product
  // with it does not depend on its length.
  void normalField(const FacetPoint& p, double* n, double* dn) const {
    for (int i = 0; i < 2; ++i) {
      n[i] = dn[i] = 0.0;
      for (int j = 0; j < ref.numNodes(); ++j)
        n[i] += p.N[j] * normals[j][i], dn[i] += p.dN[j] * normals[j][i];
    }
  }

  // xi where the normal line through x_S(xi) passes through `point`: (x_S - point) x n = 0.
  // False when Newton does not converge (a point far beyond a curved slave's ends).
  bool projectOnSlave(const double* point, double& xi) const {
    FacetPoint p;
    xi = 0.0;
    double previous = HUGE_VAL;
    for (int it = 0; it < kMaxNewton; ++it) {
      evaluate(ref, facet.coords.data(), &xi, p);
      double n[2], dn[2];
      normalField(p, n, dn);
      const double r[2] = {p.x[0] - point[0], p.x[1] - point[1]};
      const double f = cross2(r, n), df = cross2(p.a[0], n) + cross2(r, dn);
      if (!(std::abs(df) > 0.0)) return false;
      const double step = -f / df;
      if (newtonConverged(std::abs(step), previous)) return true;
      xi += step;
      previous = std::abs(step);
      if (!(std::abs(xi) < 1e3)) return false;
    }
    return false;
  }
};

// eta on the master where the line point + s n meets it, Newton from etaStart (returned).
double projectOnMaster(const Facet& master, const ReferenceElement& ref, const double* point,
                       const double* n, double etaStart, FacetPoint& p) {
  double eta = etaStart, previous = HUGE_VAL;
  for (int it = 0; it < kMaxNewton; ++it) {
    evaluate(ref, master.coords.data(), &eta, p);
    const double r[2] = {p.x[0] - point[0], p.x[1] - point[1]};
    const double dg = cross2(p.a[0], n);
    if (!(std::abs(dg) > 0.0)) break;
    const double step = -cross2(r, n) / dg;
    if (newtonConverged(std::abs(step), previous)) return eta;
    eta += step;
    previous = std::abs(step);
  }
  throw std::runtime_error("mortar integration: the projection along the slave normal onto " +
                           describe(master) + " did not converge");
}

void integrate2d(const Facet& slave, const std::vector<std::array<double, 3>>& normals,
                 const std::vector<const Facet*>& masters, const SurfaceWeight& weight,
                 double searchDistance, MortarIntegrals& out) {
  const ReferenceElement& sref = ReferenceElement::get(slave.type);
  const int ns = sref.numNodes();
  const SlaveLine line{slave, sref, normals};
  {
    // A normal field tangent to the slave would project every master to one point.
    FacetPoint p;
    const double centre = 0.0;
    evaluate(sref, slave.coords.data(), &centre, p);
    double n[2], dn[2];
    line.normalField(p, n, dn);
    if (!(std::abs(cross2(p.a[0], n)) >
          1e-8 * std::hypot(p.a[0][0], p.a[0][1]) * std::hypot(n[0], n[1])))
      throw std::invalid_argument("mortar integration: the nodal normals of slave " +
                                  describe(slave) + " are tangent to it (or zero)");
  }
  std::vector<MasterOverlap> overlaps;
  for (std::size_t m = 0; m < masters.size(); ++m) {
    const Facet& master = *masters[m];
    const ReferenceElement& mref = ReferenceElement::get(master.type);
    const int nm = mref.numNodes();
    // Nodes 0 and 1 are the ends (eta = -1, +1) of line2 and line3.
    double xiEnd[2];
    if (!line.projectOnSlave(&master.coords[0], xiEnd[0]) ||
        !line.projectOnSlave(&master.coords[3], xiEnd[1]))
      continue;
    const double lo = std::max(-1.0, std::min(xiEnd[0], xiEnd[1]));
    const double hi = std::min(1.0, std::max(xiEnd[0], xiEnd[1]));
    if (!(hi - lo > 2 * kSliver)) continue;
    // The slave point at xi (ps) and the master point its normal line meets (pm), from the
    // ends' correspondence interpolated linearly (exact for straight facets); returns eta.
    const auto meetMaster = [&](double xi, FacetPoint& ps, FacetPoint& pm) {
      evaluate(sref, slave.coords.data(), &xi, ps);
      double n[2], dn[2];
      line.normalField(ps, n, dn);
      const double etaStart = -1.0 + 2.0 * (xi - xiEnd[0]) / (xiEnd[1] - xiEnd[0]);
      return projectOnMaster(master, mref, ps.x, n, etaStart, pm);
    };
    // The ends' projections can also meet through the slave's extrapolation (|xi| >> 1 on a
    // curved slave, where the interpolated normals swing): a distant master's two ends then
    // land on both sides of the slave. A true overlap's middle meets the master inside it.
    {
      FacetPoint ps, pm;
      double eta = HUGE_VAL;
      try {
        eta = meetMaster(0.5 * (lo + hi), ps, pm);
      } catch (const std::runtime_error&) {
      }
      if (!(std::abs(eta) <= 1.0 + 1e-6)) continue;
    }
    const int degree = 2 * (info(slave.type).order + info(master.type).order) + 2;
    const QuadratureRule& rule = quadratureRule(ElementType::Line2, degree);
    MasterOverlap overlap = newOverlap(m, ns, nm);
    for (int q = 0; q < rule.size(); ++q) {
      FacetPoint ps, pm;
      meetMaster(0.5 * (lo + hi) + 0.5 * (hi - lo) * rule.points[q], ps, pm);
      double geometric[3], nM[3], n[3] = {0, 0, 0}, dn[2];
      const double dA = 0.5 * (hi - lo) * rule.weights[q] *
                        areaElement(slave, 2, ps.dN, geometric) * (weight ? weight(ps.x) : 1.0);
      line.normalField(ps, n, dn);
      const double length = std::hypot(n[0], n[1]);
      n[0] /= length, n[1] /= length;
      areaElement(master, 2, pm.dN, nM);
      accumulate(ns, ps, nm, pm, n, nM, dA, overlap);
    }
    overlaps.push_back(std::move(overlap));
  }
  // The size is the segment's length (its area is weighted by 2 pi r on rings); 3D takes the
  // square root of the area, which keeps an elongated facet's size near its short side.
  addNearestSurface(overlaps, facetDiameter(slave), searchDistance, out);
}

// ---- 3D: auxiliary plane ----

// The point of facet f that projects along n0 onto `target` of the plane: Newton on its plane
// coordinates from the facet centre; p holds the facet's shapes there.
void projectOnPlanePoint(const Facet& f, const ReferenceElement& ref, const AuxiliaryPlane& plane,
                         const Point2& target, FacetPoint& p) {
  double xi[2], previous = HUGE_VAL;
  facetCentre(f.type, xi);
  for (int it = 0; it < kMaxNewton; ++it) {
    evaluate(ref, f.coords.data(), xi, p);
    const Point2 c = plane.coordinates(p.x);
    const double r[2] = {target[0] - c[0], target[1] - c[1]};
    const double* t1 = plane.t1.data();
    const double* t2 = plane.t2.data();
    const double J[2][2] = {{dot3(p.a[0], t1), dot3(p.a[1], t1)},
                            {dot3(p.a[0], t2), dot3(p.a[1], t2)}};
    const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    if (!(std::abs(det) > 1e-14 * std::sqrt(dot3(p.a[0], p.a[0]) * dot3(p.a[1], p.a[1])))) break;
    const double d0 = (J[1][1] * r[0] - J[0][1] * r[1]) / det;
    const double d1 = (J[0][0] * r[1] - J[1][0] * r[0]) / det;
    const double step = std::max(std::abs(d0), std::abs(d1));
    if (newtonConverged(step, previous)) return;
    xi[0] += d0, xi[1] += d1;
    previous = step;
  }
  throw std::runtime_error(
      "mortar integration: the projection along the auxiliary plane's normal "
      "onto " +
      describe(f) + " did not converge");
}

void integrate3d(const Facet& slave, const std::vector<std::array<double, 3>>& normals,
                 const std::vector<const Facet*>& masters, double searchDistance,
                 MortarIntegrals& out) {
  const ReferenceElement& sref = ReferenceElement::get(slave.type);
  const int ns = sref.numNodes();
  AuxiliaryPlane plane;
  {
    double xi[2];
    facetCentre(slave.type, xi);
    FacetPoint p;
    evaluate(sref, slave.coords.data(), xi, p);
    std::copy(p.x, p.x + 3, plane.x0.begin());
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < ns; ++j)
        plane.n0[i] += p.N[j] * normals[j][i];
    const double norm = std::sqrt(dot3(plane.n0.data(), plane.n0.data()));
    if (!(norm > 1e-12))
      throw std::invalid_argument("mortar integration: the nodal normals of slave " +
                                  describe(slave) + " cancel at its centre");
    for (double& c : plane.n0)
      c /= norm;
    tangentBasis(3, plane.n0, plane.t1, plane.t2);
  }
  const double minArea = kSliver * out.area;
  const std::vector<Polygon2> slavePieces = projectedPolygons(slave, plane, minArea);
  double projectedArea = 0.0;
  for (const Polygon2& piece : slavePieces)
    projectedArea += signedArea(piece);
  if (!(projectedArea > 1e-8 * out.area))
    throw std::invalid_argument("mortar integration: the auxiliary plane of slave " +
                                describe(slave) + " is perpendicular to it (nodal normals " +
                                "tangent to the facet)");
  const double tolerance = kSliver * std::sqrt(projectedArea);
  std::vector<MasterOverlap> overlapsFound;
  for (std::size_t m = 0; m < masters.size(); ++m) {
    const Facet& master = *masters[m];
    const ReferenceElement& mref = ReferenceElement::get(master.type);
    const int nm = mref.numNodes();
    const int degree = std::max(shapeDegree(slave.type) + shapeDegree(master.type),
                                2 * info(slave.type).order + 2);
    const QuadratureRule& rule = quadratureRule(ElementType::Tri3, degree);
    MasterOverlap overlap = newOverlap(m, ns, nm);
    bool overlaps = false;
    for (const Polygon2& masterPiece : projectedPolygons(master, plane, minArea))
      for (const Polygon2& slavePiece : slavePieces) {
        const Polygon2 cell = clipConvex(slavePiece, masterPiece, tolerance);
        if (cell.empty() || signedArea(cell) <= minArea) continue;
        overlaps = true;
        // Fan from the first vertex (the cell is convex): n - 2 triangles where a fan from the
        // centroid needs n, and thin triangles are harmless to the polynomial integrands.
        const Point2& c = cell[0];
        for (std::size_t e = 1; e + 1 < cell.size(); ++e) {
          const Point2& a = cell[e];
          const Point2& b = cell[e + 1];
          const double twiceArea = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]);
          for (int q = 0; q < rule.size(); ++q) {
            const double r = rule.points[2 * q], s = rule.points[2 * q + 1];
            const Point2 x{c[0] + r * (a[0] - c[0]) + s * (b[0] - c[0]),
                           c[1] + r * (a[1] - c[1]) + s * (b[1] - c[1])};
            FacetPoint ps, pm;
            projectOnPlanePoint(slave, sref, plane, x, ps);
            projectOnPlanePoint(master, mref, plane, x, pm);
            double nS[3], nM[3];
            areaElement(slave, 3, ps.dN, nS);
            areaElement(master, 3, pm.dN, nM);
            const double dA = rule.weights[q] * twiceArea / std::abs(dot3(nS, plane.n0.data()));
            accumulate(ns, ps, nm, pm, plane.n0.data(), nM, dA, overlap);
          }
        }
      }
    if (overlaps) overlapsFound.push_back(std::move(overlap));
  }
  addNearestSurface(overlapsFound, std::sqrt(out.area), searchDistance, out);
}

// The standard-basis integrals (D = int N_j N_k, M = int N_j N^M_l) into the basis Phi = B N:
// D <- B D, M <- B M.
void changeBasis(const std::vector<double>& B, int ns, MortarIntegrals& out) {
  auto transform = [&](std::vector<double>& X, int columns) {
    std::vector<double> Y(X.size(), 0.0);
    for (int j = 0; j < ns; ++j)
      for (int i = 0; i < ns; ++i)
        for (int c = 0; c < columns; ++c)
          Y[j * columns + c] += B[j * ns + i] * X[i * columns + c];
    X.swap(Y);
  };
  transform(out.D, ns);
  for (MortarMaster& m : out.masters)
    transform(m.M, static_cast<int>(m.M.size()) / ns);
}

// The standard-basis integrals over the covered part into the dual basis Phi = A T N (T the
// quadratic transform, else the identity). On a partially covered facet A is built on the
// covered part where it exists (A = diag(int_c T N) (int_c T N (T N)^T)^-1, Cichosz & Bischoff
// 2011): D stays diagonal (against T N) with the covered integrals and sum_l M_jl = sum_k D_jk,
// where the whole facet's basis would couple the nodes and give weights near zero or negative.
// It exists when every int_c T N_j > 0, always on linear facets; a quadratic facet's function
// can integrate to a negative value over part of it, and there the whole facet's basis is kept.
// A sliver (covered mass matrix singular in double precision) counts as no coverage.
void toDualBasis(const std::vector<double>& whole, const std::vector<double>& T, int ns,
                 MortarIntegrals& out) {
  std::vector<double> B = whole;
  if (out.coveredArea < 1e-6 * out.area) {
    out.D.assign(out.D.size(), 0.0);
    out.masters.clear();
    out.coveredArea = 0.0;
    return;
  }
  if (out.coveredArea < (1.0 - 1e-9) * out.area) {
    // int_c T N (T N)^T = T D T^T, and its row sums int_c T N (the columns of T sum to 1).
    const std::vector<double> mass = multiply(ns, multiply(ns, T, out.D), T, true);
    std::vector<double> rowSums(ns, 0.0);
    for (int j = 0; j < ns; ++j)
      for (int k = 0; k < ns; ++k)
        rowSums[j] += mass[j * ns + k];
    if (*std::min_element(rowSums.begin(), rowSums.end()) > 1e-9 * out.coveredArea) {
      std::vector<double> covered = multiply(ns, dualCoefficients(ns, rowSums, mass), T);
      if (std::all_of(covered.begin(), covered.end(), [](double a) { return std::isfinite(a); }))
        B.swap(covered);
    }
  }
  changeBasis(B, ns, out);
}

}  // namespace

bool hasTransformedBasis(ElementType type) {
  return type == ElementType::Tri6 || type == ElementType::Quad8;
}

std::vector<double> multiplierBasisTransform(ElementType type) {
  const int n = info(type).nodes;
  std::vector<double> T(static_cast<std::size_t>(n) * n, 0.0);
  for (int j = 0; j < n; ++j)
    T[j * n + j] = 1.0;
  if (!hasTransformedBasis(type)) return T;
  // Corner i gains alpha of the mid-edge functions beside it; mid-edge node c + i sits between
  // corners i and i + 1 (gmsh order) and keeps 1 - 2 alpha of its own.
  constexpr double alpha = kTransformAlpha;
  const int corners = n / 2;
  for (int i = 0; i < corners; ++i) {
    const int mid = corners + i;
    T[mid * n + mid] = 1.0 - 2.0 * alpha;
    T[i * n + mid] += alpha;
    T[((i + 1) % corners) * n + mid] += alpha;
  }
  return T;
}

std::vector<double> facetBasisTransform(ElementType type, const std::vector<double>& lumped) {
  if (type != ElementType::Line3) return multiplierBasisTransform(type);
  // A line3 corner whose weighted integral vanishes: on an axisymmetric ring the corner on the
  // axis integrates N r to 0 (int_0^1 (1 - 3 s + 2 s^2) s ds = 0), so neither basis would give
  // it a weight. The corners then gain alpha of the mid node's function, as on tri6 and quad8:
  // int T N r dr = alpha / 3, 1/6 + alpha / 3 and (1 - 2 alpha) / 3 (times 2 pi h^2). The test
  // is a share, not a sign: deformed, the axis facet's corner integrates to +-1e-8 of its area
  // (its mid node off the middle), while a corner's share is 1/6 on a plane facet and 1/9 on a
  // ring's second facet from the axis; 1/20 tells them apart.
  const double area = std::accumulate(lumped.begin(), lumped.end(), 0.0);
  std::vector<double> T = multiplierBasisTransform(type);
  if (std::min(lumped[0], lumped[1]) > 0.05 * area) return T;
  constexpr double alpha = kTransformAlpha;
  T[2 * 3 + 2] = 1.0 - 2.0 * alpha;
  T[0 * 3 + 2] += alpha;
  T[1 * 3 + 2] += alpha;
  return T;
}

std::vector<double> dualBasisCoefficients(const Facet& slave) {
  std::vector<double> mass;
  const std::vector<double> lumped = wholeFacetIntegrals(slave, checkFacet(slave), &mass);
  return wholeFacetDualBasis(slave, lumped, mass, facetBasisTransform(slave.type, lumped));
}

MortarIntegrals integrateWholeFacet(const Facet& slave, MultiplierBasis basis,
                                    const SurfaceWeight& weight, const FacetField& field) {
  const int spaceDim = checkFacet(slave);
  if (weight && spaceDim != 2)
    throw std::invalid_argument("mortar integration: a weighted measure is for 2D (line) facets");
  const int ns = info(slave.type).nodes;
  MortarIntegrals out;
  std::vector<double> fieldIntegrals;
  const std::vector<double> lumped = wholeFacetIntegrals(slave, spaceDim, &out.D, weight, field,
                                                         field ? &fieldIntegrals : nullptr);
  out.area = out.coveredArea = std::accumulate(lumped.begin(), lumped.end(), 0.0);
  const std::vector<double> T = facetBasisTransform(slave.type, lumped);
  const std::vector<double> B =
      basis == MultiplierBasis::Dual ? wholeFacetDualBasis(slave, lumped, out.D, T) : T;
  changeBasis(B, ns, out);
  out.field.assign(field ? ns : 0, 0.0);
  for (std::size_t j = 0; j < out.field.size(); ++j)
    for (int k = 0; k < ns; ++k)
      out.field[j] += B[j * ns + k] * fieldIntegrals[k];
  return out;
}

MortarIntegrals integrateMortar(const Facet& slave,
                                const std::vector<std::array<double, 3>>& slaveNormals,
                                const std::vector<const Facet*>& masters, MultiplierBasis basis,
                                const SurfaceWeight& weight, double searchDistance) {
  const int spaceDim = checkFacet(slave);
  if (weight && spaceDim != 2)
    throw std::invalid_argument("mortar integration: a weighted measure is for 2D (line) facets");
  const int ns = info(slave.type).nodes;
  if (slaveNormals.size() != static_cast<std::size_t>(ns))
    throw std::invalid_argument("mortar integration: " + std::to_string(slaveNormals.size()) +
                                " nodal normals given for the " + std::to_string(ns) +
                                " nodes of slave " + describe(slave));
  for (const Facet* master : masters) {
    if (checkFacet(*master) != spaceDim)
      throw std::invalid_argument("mortar integration: master " + describe(*master) +
                                  " does not have the dimension of slave " + describe(slave));
    // A degenerate master would otherwise surface as a non-converging projection.
    double xi[2], normal[3];
    FacetPoint p;
    facetCentre(master->type, xi);
    evaluate(ReferenceElement::get(master->type), master->coords.data(), xi, p);
    areaElement(*master, spaceDim, p.dN, normal);
  }
  MortarIntegrals out;
  out.D.assign(static_cast<std::size_t>(ns) * ns, 0.0);
  const bool dual = basis == MultiplierBasis::Dual;
  std::vector<double> mass;
  const std::vector<double> lumped =
      wholeFacetIntegrals(slave, spaceDim, dual ? &mass : nullptr, weight);
  out.area = std::accumulate(lumped.begin(), lumped.end(), 0.0);
  const std::vector<double> T = facetBasisTransform(slave.type, lumped);
  // Checks the dual basis exists before integrating (a sentence, not a singular matrix).
  const std::vector<double> whole =
      dual ? wholeFacetDualBasis(slave, lumped, mass, T) : std::vector<double>();
  if (spaceDim == 2)
    integrate2d(slave, slaveNormals, masters, weight, searchDistance, out);
  else
    integrate3d(slave, slaveNormals, masters, searchDistance, out);
  if (dual && out.coveredArea > 0)
    toDualBasis(whole, T, ns, out);
  else if (!dual && !isIdentity(T, ns))
    changeBasis(T, ns, out);
  return out;
}

}  // namespace contactlab
