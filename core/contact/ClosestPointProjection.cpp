#include "core/contact/ClosestPointProjection.hpp"

#include "core/fem/ReferenceElement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace contactlab {
namespace {

constexpr int kMaxNodes = 9;
// Longest Newton step (infinity norm, reference coordinates) and how far the unconstrained
// iterates may leave the reference facet before the boundary search takes over.
constexpr double kMaxStep = 1.0;
constexpr double kEscapeMargin = 1.0;
// Armijo sufficient-decrease constant and number of step halvings.
constexpr double kArmijo = 1e-4;
constexpr int kMaxHalvings = 40;

double dot3(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

bool isSimplex(ElementType t) {
  return t == ElementType::Tri3 || t == ElementType::Tri6;
}

// Geometry of the facet at a reference point: position, tangents and second derivatives.
struct FacetPoint {
  double x[3];
  double a[2][3];     // dx/dxi_j
  double b[2][2][3];  // d2x/dxi_j dxi_k
};

class FacetMap {
 public:
  FacetMap(ElementType type, const double* coords)
      : ref_(ReferenceElement::get(type)), x_(coords), dim_(ref_.dim()), n_(ref_.numNodes()) {}

  int dim() const { return dim_; }

  void position(const double* xi, double* x) const {
    double N[kMaxNodes];
    ref_.shape(xi, N);
    for (int i = 0; i < 3; ++i) {
      x[i] = 0.0;
      for (int a = 0; a < n_; ++a)
        x[i] += N[a] * x_[3 * a + i];
    }
  }

  void tangents(const double* xi, double (&t)[2][3]) const {
    double dN[2 * kMaxNodes];
    ref_.shapeDerivatives(xi, dN);
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        t[j][i] = 0.0;
        if (j < dim_)
          for (int a = 0; a < n_; ++a)
            t[j][i] += dN[a * dim_ + j] * x_[3 * a + i];
      }
  }

  // Second derivatives by central differences of the first ones: exact (up to round-off) for
  // every supported facet, whose shape-function derivatives are at most quadratic in each
  // reference coordinate separately.
  void evaluate(const double* xi, FacetPoint& p) const {
    position(xi, p.x);
    tangents(xi, p.a);
    const double h = 0.5;
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i)
          p.b[j][k][i] = 0.0;
    for (int k = 0; k < dim_; ++k) {
      double xp[2] = {xi[0], dim_ > 1 ? xi[1] : 0.0}, xm[2] = {xp[0], xp[1]};
      xp[k] += h, xm[k] -= h;
      double tp[2][3], tm[2][3];
      tangents(xp, tp);
      tangents(xm, tm);
      for (int j = 0; j < dim_; ++j)
        for (int i = 0; i < 3; ++i)
          p.b[j][k][i] = (tp[j][i] - tm[j][i]) / (2 * h);
    }
    if (dim_ == 2)
      for (int i = 0; i < 3; ++i)
        p.b[0][1][i] = p.b[1][0][i] = 0.5 * (p.b[0][1][i] + p.b[1][0][i]);
  }

 private:
  const ReferenceElement& ref_;
  const double* x_;
  int dim_, n_;
};

// How far xi lies outside the reference facet (<= 0 inside), in reference coordinates.
double outside(ElementType t, int dim, const double* xi) {
  if (isSimplex(t)) return std::max({-xi[0], -xi[1], xi[0] + xi[1] - 1.0});
  double d = std::fabs(xi[0]) - 1.0;
  if (dim > 1) d = std::max(d, std::fabs(xi[1]) - 1.0);
  return d;
}

// Minimisation of f(s) = |x(xi(s)) - x_s|^2 / 2 over an affine parametrisation
// xi = origin + D s of m = 1 or 2 parameters: the whole facet (D = identity, unconstrained with
// an escape guard) or one boundary edge (m = 1, s clamped to [0, 1]).
struct Search {
  const FacetMap& map;
  ElementType type;
  const double* xs;
  double origin[2];
  double D[2][2];  // D[j][p] = dxi_j / ds_p
  int m;
  bool clamped;
};

struct SearchResult {
  double xi[2] = {0.0, 0.0};
  double f = std::numeric_limits<double>::infinity();
  int iterations = 0;
  bool converged = false;
  bool escaped = false;
};

void toXi(const Search& s, const double* p, double* xi) {
  for (int j = 0; j < 2; ++j) {
    xi[j] = s.origin[j];
    for (int q = 0; q < s.m; ++q)
      xi[j] += s.D[j][q] * p[q];
  }
}

double objective(const Search& s, const double* p) {
  double xi[2], x[3];
  toXi(s, p, xi);
  s.map.position(xi, x);
  const double r[3] = {x[0] - s.xs[0], x[1] - s.xs[1], x[2] - s.xs[2]};
  return 0.5 * dot3(r, r);
}

// Solves the m x m system A d = rhs; returns false unless A is positive definite.
bool solveSpd(int m, const double (&A)[2][2], const double* rhs, double* d) {
  if (m == 1) {
    if (!(A[0][0] > 0.0)) return false;
    d[0] = rhs[0] / A[0][0];
    return true;
  }
  const double det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
  const double scale = A[0][0] * A[1][1];
  if (!(A[0][0] > 0.0) || !(det > 1e-14 * std::fabs(scale))) return false;
  d[0] = (A[1][1] * rhs[0] - A[0][1] * rhs[1]) / det;
  d[1] = (A[0][0] * rhs[1] - A[1][0] * rhs[0]) / det;
  return true;
}

SearchResult minimise(const Search& s, const double* start, double tol, int maxIterations) {
  SearchResult res;
  double p[2] = {start[0], s.m > 1 ? start[1] : 0.0};
  const double xsNorm2 = dot3(s.xs, s.xs);
  FacetPoint fp;
  for (int it = 0; it < maxIterations; ++it) {
    double xi[2];
    toXi(s, p, xi);
    s.map.evaluate(xi, fp);
    const double r[3] = {fp.x[0] - s.xs[0], fp.x[1] - s.xs[1], fp.x[2] - s.xs[2]};
    const double f = 0.5 * dot3(r, r);
    // Derivatives with respect to the parameters: x_p = a_j D_jp, x_pq = b_jk D_jp D_kq.
    double xp[2][3] = {{0, 0, 0}, {0, 0, 0}}, xpq[2][2][3] = {};
    const int dim = s.map.dim();
    for (int q = 0; q < s.m; ++q)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < dim; ++j) {
          xp[q][i] += fp.a[j][i] * s.D[j][q];
          for (int q2 = 0; q2 < s.m; ++q2)
            for (int k = 0; k < dim; ++k)
              xpq[q][q2][i] += fp.b[j][k][i] * s.D[j][q] * s.D[k][q2];
        }
    double g[2] = {0, 0}, M[2][2] = {}, H[2][2] = {};
    for (int q = 0; q < s.m; ++q) {
      g[q] = dot3(r, xp[q]);
      for (int q2 = 0; q2 < s.m; ++q2) {
        M[q][q2] = dot3(xp[q], xp[q2]);
        H[q][q2] = M[q][q2] + dot3(r, xpq[q][q2]);
      }
    }
    const double minusG[2] = {-g[0], -g[1]};
    double d[2] = {0, 0};
    if (!solveSpd(s.m, H, minusG, d)) {
      // H is not positive definite: Gauss-Newton direction (steepest descent if the metric is
      // degenerate too) plus a direction of negative curvature, so that Newton leaves maxima and
      // saddles of the distance (e.g. the centre of a facet curving away from a far point).
      if (!solveSpd(s.m, M, minusG, d)) {
        const double gn = std::max(std::fabs(g[0]), std::fabs(g[1]));
        if (gn > 0.0) d[0] = -g[0] / gn, d[1] = -g[1] / gn;
      }
      double v[2] = {0.0, 0.0};
      if (s.m == 1) {
        if (H[0][0] <= 0.0) v[0] = 1.0;
      } else {
        const double mean = 0.5 * (H[0][0] + H[1][1]);
        const double rad = std::hypot(0.5 * (H[0][0] - H[1][1]), H[0][1]);
        const double lmin = mean - rad;
        if (lmin <= 0.0) {
          const double v1[2] = {H[0][1], lmin - H[0][0]}, v2[2] = {lmin - H[1][1], H[0][1]};
          const bool first = std::hypot(v1[0], v1[1]) >= std::hypot(v2[0], v2[1]);
          v[0] = first ? v1[0] : v2[0], v[1] = first ? v1[1] : v2[1];
          const double vn = std::max(std::fabs(v[0]), std::fabs(v[1]));
          if (vn > 0.0) {
            v[0] /= vn, v[1] /= vn;
          } else {
            v[0] = 1.0, v[1] = 0.0;  // H = 0: any direction has non-positive curvature
          }
        }
      }
      if (g[0] * v[0] + g[1] * v[1] > 0.0) v[0] = -v[0], v[1] = -v[1];
      d[0] += kMaxStep * v[0], d[1] += kMaxStep * v[1];
      if (d[0] == 0.0 && d[1] == 0.0) {
        res.converged = true;
        break;
      }
    }
    const double dn = std::max(std::fabs(d[0]), std::fabs(d[1]));
    if (dn > kMaxStep) d[0] *= kMaxStep / dn, d[1] *= kMaxStep / dn;
    // Clamped edge search: a KKT point on the bound is a converged answer.
    if (s.clamped && ((p[0] <= 0.0 && d[0] <= 0.0) || (p[0] >= 1.0 && d[0] >= 0.0))) {
      res.converged = true;
      break;
    }
    // Armijo backtracking; the slack absorbs round-off in f once the steps are tiny.
    const double slack = 1e-14 * (f + dot3(fp.x, fp.x) + xsNorm2);
    double alpha = 1.0, pNew[2] = {p[0], p[1]}, step[2] = {0, 0};
    bool accepted = false;
    for (int h = 0; h < kMaxHalvings && !accepted; ++h, alpha *= 0.5) {
      pNew[0] = p[0] + alpha * d[0], pNew[1] = p[1] + alpha * d[1];
      if (s.clamped) pNew[0] = std::min(1.0, std::max(0.0, pNew[0]));
      step[0] = pNew[0] - p[0], step[1] = s.m > 1 ? pNew[1] - p[1] : 0.0;
      const double fNew = objective(s, pNew);
      accepted = fNew <= f + kArmijo * (g[0] * step[0] + g[1] * step[1]) + slack;
    }
    ++res.iterations;
    if (!accepted) break;  // no descent left: not converged
    p[0] = pNew[0], p[1] = pNew[1];
    if (std::max(std::fabs(step[0]), std::fabs(step[1])) <= tol) {
      res.converged = true;
      break;
    }
    if (!s.clamped) {
      double xiNew[2];
      toXi(s, p, xiNew);
      if (outside(s.type, dim, xiNew) > kEscapeMargin) {
        res.escaped = true;
        break;
      }
    }
  }
  toXi(s, p, res.xi);
  res.f = objective(s, p);
  return res;
}

void checkFacetType(ElementType t, int spaceDim) {
  const bool ok2 = t == ElementType::Line2 || t == ElementType::Line3;
  const bool ok3 = t == ElementType::Tri3 || t == ElementType::Tri6 || t == ElementType::Quad4 ||
                   t == ElementType::Quad8 || t == ElementType::Quad9;
  if ((spaceDim == 2 && ok2) || (spaceDim == 3 && ok3)) return;
  throw std::invalid_argument("projectOnFacet: facet type '" + std::string(info(t).name) +
                              "' in spaceDim " + std::to_string(spaceDim) +
                              "; expected line2/line3 in 2D or tri3/tri6/quad4/quad8/quad9 in 3D");
}

}  // namespace

bool insideReferenceFacet(ElementType facetType, const double* xi, double tolerance) {
  return outside(facetType, info(facetType).dim, xi) <= tolerance;
}

Projection projectOnFacet(ElementType facetType, int spaceDim, const double* facetCoords,
                          const double* slavePoint, double tolerance, int maxIterations) {
  checkFacetType(facetType, spaceDim);
  const FacetMap map(facetType, facetCoords);
  const int dim = map.dim();
  const bool simplex = isSimplex(facetType);
  Projection out;

  // A coarse sampling of the facet (a lattice of spacing 1/4 of the reference domain, which holds
  // the nodes): the closest samples, interior and on the boundary, are points of the facet, so
  // upper bounds of the minimum that reveal a Newton solution stuck in a poorer local minimum.
  const double inf = std::numeric_limits<double>::infinity();
  double closestSample[2] = {0.0, 0.0};
  double fSample = inf, fBoundarySample = inf;
  const int steps = 4;
  for (int i = 0; i <= steps; ++i)
    for (int j = 0; j <= (dim > 1 ? steps : 0); ++j) {
      if (simplex && i + j > steps) continue;
      const double xi[2] = {
          simplex ? double(i) / steps : -1.0 + 2.0 * i / steps,
          dim == 1 ? 0.0 : (simplex ? double(j) / steps : -1.0 + 2.0 * j / steps)};
      double x[3];
      map.position(xi, x);
      const double r[3] = {x[0] - slavePoint[0], x[1] - slavePoint[1], x[2] - slavePoint[2]};
      const double f = 0.5 * dot3(r, r);
      if (f < fSample) fSample = f, closestSample[0] = xi[0], closestSample[1] = xi[1];
      if (outside(facetType, dim, xi) > -1e-12) fBoundarySample = std::min(fBoundarySample, f);
    }
  auto improves = [](double f, double fBest) { return f < fBest - 1e-12 * std::fabs(fBest); };

  // Stage 1: unconstrained Newton from the centre, and again from the closest sample when that is
  // closer than the answer found.
  Search whole{map, facetType, slavePoint, {0.0, 0.0}, {{1.0, 0.0}, {0.0, 1.0}}, dim, false};
  const double centre[2] = {simplex ? 1.0 / 3.0 : 0.0, simplex ? 1.0 / 3.0 : 0.0};
  SearchResult best;  // the best interior candidate so far
  auto interiorFrom = [&](const double* start) {
    const SearchResult r = minimise(whole, start, tolerance, maxIterations);
    out.iterations += r.iterations;
    const bool interior = !r.escaped && insideReferenceFacet(facetType, r.xi);
    if (interior && (improves(r.f, best.f) || (r.converged && !best.converged && r.f <= best.f)))
      best = r;
  };
  interiorFrom(centre);
  if (improves(fSample, best.f)) interiorFrom(closestSample);
  bool interior = best.f < inf;

  // Stage 2: closest point of the boundary (vertices, then edges in 3D), unless a converged
  // interior minimum beats every boundary sample.
  if (!(interior && best.converged) || improves(fBoundarySample, best.f)) {
    SearchResult boundary;
    double vertices[4][2];
    int nv;
    if (dim == 1) {
      nv = 2;
      vertices[0][0] = -1.0, vertices[1][0] = 1.0, vertices[0][1] = vertices[1][1] = 0.0;
    } else if (simplex) {
      nv = 3;
      const double v[3][2] = {{0, 0}, {1, 0}, {0, 1}};
      std::copy(&v[0][0], &v[0][0] + 6, &vertices[0][0]);
    } else {
      nv = 4;
      const double v[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      std::copy(&v[0][0], &v[0][0] + 8, &vertices[0][0]);
    }
    for (int v = 0; v < nv; ++v) {
      const Search at{map, facetType, slavePoint, {vertices[v][0], vertices[v][1]}, {}, 1, true};
      const double zero = 0.0;
      const double f = objective(at, &zero);
      if (f < boundary.f) {
        boundary = SearchResult();
        boundary.xi[0] = vertices[v][0], boundary.xi[1] = vertices[v][1];
        boundary.f = f;
        boundary.converged = true;
      }
    }
    if (dim == 2)
      for (int e = 0; e < nv; ++e) {
        const double* A = vertices[e];
        const double* B = vertices[(e + 1) % nv];
        const Search edge{
            map, facetType, slavePoint, {A[0], A[1]}, {{B[0] - A[0], 0.0}, {B[1] - A[1], 0.0}},
            1,   true};
        const double mid = 0.5;
        const SearchResult r = minimise(edge, &mid, tolerance, maxIterations);
        out.iterations += r.iterations;
        if (r.f < boundary.f) boundary = r;
      }
    if (!interior || boundary.f < best.f || (!best.converged && boundary.f <= best.f)) {
      best = boundary;
      interior = false;
    }
  }
  out.inside = interior && best.converged;
  out.converged = best.converged;
  out.xi[0] = best.xi[0], out.xi[1] = dim > 1 ? best.xi[1] : 0.0;

  map.position(out.xi, out.point);
  double d[3];
  for (int i = 0; i < 3; ++i)
    d[i] = slavePoint[i] - out.point[i];
  out.distance = std::sqrt(dot3(d, d));
  // Normal (facetGeometry's convention); at a degenerate point, the normal at the centre.
  for (int attempt = 0; attempt < 2; ++attempt) {
    double t[2][3];
    map.tangents(attempt == 0 ? out.xi : centre, t);
    double n[3];
    if (dim == 1) {
      n[0] = t[0][1], n[1] = -t[0][0], n[2] = 0.0;
    } else {
      n[0] = t[0][1] * t[1][2] - t[0][2] * t[1][1];
      n[1] = t[0][2] * t[1][0] - t[0][0] * t[1][2];
      n[2] = t[0][0] * t[1][1] - t[0][1] * t[1][0];
    }
    const double len = std::sqrt(dot3(n, n));
    const double scale = dim == 1 ? 0.0 : std::sqrt(dot3(t[0], t[0]) * dot3(t[1], t[1]));
    if (len > 1e-12 * scale && len > 0.0) {
      for (int i = 0; i < 3; ++i)
        out.normal[i] = n[i] / len;
      break;
    }
  }
  out.gap = dot3(d, out.normal);
  return out;
}

Projection projectOnFacetExtension(ElementType facetType, int spaceDim, const double* facetCoords,
                                   const double* slavePoint, const double* xiStart,
                                   int maxIterations) {
  checkFacetType(facetType, spaceDim);
  const FacetMap map(facetType, facetCoords);
  const int m = map.dim();
  Projection out;
  double xi[2] = {xiStart[0], m > 1 ? xiStart[1] : 0.0};
  FacetPoint p;
  for (int it = 0; it < maxIterations; ++it) {
    map.evaluate(xi, p);
    const double r[3] = {p.x[0] - slavePoint[0], p.x[1] - slavePoint[1], p.x[2] - slavePoint[2]};
    double g[2] = {0.0, 0.0}, H[2][2] = {{1.0, 0.0}, {0.0, 1.0}};
    for (int j = 0; j < m; ++j) {
      g[j] = dot3(r, p.a[j]);
      for (int k = 0; k < m; ++k)
        H[j][k] = dot3(p.a[j], p.a[k]) + dot3(r, p.b[j][k]);
    }
    const double det = H[0][0] * H[1][1] - H[0][1] * H[1][0];
    if (!(std::fabs(det) > 1e-300)) break;
    const double d[2] = {-(H[1][1] * g[0] - H[0][1] * g[1]) / det,
                         -(H[0][0] * g[1] - H[1][0] * g[0]) / det};
    xi[0] += d[0];
    if (m > 1) xi[1] += d[1];
    out.iterations = it + 1;
    if (std::fabs(d[0]) + std::fabs(m > 1 ? d[1] : 0.0) < 1e-14) {
      out.converged = true;
      break;
    }
  }
  map.evaluate(xi, p);
  double n[3];
  if (m == 1) {
    n[0] = p.a[0][1], n[1] = -p.a[0][0], n[2] = 0.0;
  } else {
    n[0] = p.a[0][1] * p.a[1][2] - p.a[0][2] * p.a[1][1];
    n[1] = p.a[0][2] * p.a[1][0] - p.a[0][0] * p.a[1][2];
    n[2] = p.a[0][0] * p.a[1][1] - p.a[0][1] * p.a[1][0];
  }
  const double norm = std::sqrt(dot3(n, n));
  const double r[3] = {slavePoint[0] - p.x[0], slavePoint[1] - p.x[1], slavePoint[2] - p.x[2]};
  for (int i = 0; i < 3; ++i) {
    out.point[i] = p.x[i];
    out.normal[i] = norm > 0 ? n[i] / norm : 0.0;
  }
  out.xi[0] = xi[0], out.xi[1] = xi[1];
  out.gap = dot3(r, out.normal);
  out.distance = std::sqrt(dot3(r, r));
  out.inside = outside(facetType, m, xi) <= kProjectionInsideTolerance;
  return out;
}

}  // namespace contactlab
