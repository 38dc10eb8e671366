#include "core/fem/QuadratureRule.hpp"

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

namespace contactlab {
namespace {

enum class Shape { Point, Line, Quad, Hex, Tri, Tet };

Shape shapeOf(ElementType type) {
  switch (type) {
    case ElementType::Point1:
      return Shape::Point;
    case ElementType::Line2:
    case ElementType::Line3:
      return Shape::Line;
    case ElementType::Tri3:
    case ElementType::Tri6:
      return Shape::Tri;
    case ElementType::Quad4:
    case ElementType::Quad8:
    case ElementType::Quad9:
      return Shape::Quad;
    case ElementType::Tet4:
    case ElementType::Tet10:
      return Shape::Tet;
    default:
      return Shape::Hex;
  }
}

// n-point Gauss-Legendre on [-1, 1] by Newton iteration on P_n (converges from the usual
// Chebyshev-like initial guesses; accurate to machine precision well beyond n = 20).
void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  const double pi = std::acos(-1.0);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double z = std::cos(pi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1, p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    const double weight = 2 / ((1 - z * z) * dp * dp);
    x[i] = -z, x[n - 1 - i] = z;
    w[i] = w[n - 1 - i] = weight;
  }
  if (n % 2 == 1) x[n / 2] = 0.0;
}

QuadratureRule tensorRule(int dim, int degree) {
  std::vector<double> x, w;
  const int n = degree / 2 + 1;
  gaussLegendre(n, x, w);
  QuadratureRule r;
  r.dim = dim;
  const int count = dim == 1 ? n : (dim == 2 ? n * n : n * n * n);
  for (int q = 0; q < count; ++q) {
    double weight = 1;
    for (int i = 0, rest = q; i < dim; ++i, rest /= n) {
      r.points.push_back(x[rest % n]);
      weight *= w[rest % n];
    }
    r.weights.push_back(weight);
  }
  return r;
}

// Gauss-Legendre mapped to [0, 1].
void unitGauss(int n, std::vector<double>& x, std::vector<double>& w) {
  gaussLegendre(n, x, w);
  for (int i = 0; i < n; ++i)
    x[i] = 0.5 * (x[i] + 1), w[i] *= 0.5;
}

// Duffy collapse of the unit square/cube. The Jacobian (1-v) resp. (1-v)(1-w)^2 raises the
// degree in the collapsed directions, hence the extra points there.
QuadratureRule collapsedRule(int dim, int degree) {
  std::vector<double> xu, wu, xv, wv, xw, ww;
  unitGauss(degree / 2 + 1, xu, wu);
  unitGauss((degree + 1) / 2 + 1, xv, wv);
  unitGauss((degree + 2) / 2 + 1, xw, ww);
  QuadratureRule r;
  r.dim = dim;
  if (dim == 2) {
    for (std::size_t j = 0; j < xv.size(); ++j)
      for (std::size_t i = 0; i < xu.size(); ++i) {
        r.points.insert(r.points.end(), {xu[i] * (1 - xv[j]), xv[j]});
        r.weights.push_back(wu[i] * wv[j] * (1 - xv[j]));
      }
    return r;
  }
  for (std::size_t k = 0; k < xw.size(); ++k)
    for (std::size_t j = 0; j < xv.size(); ++j)
      for (std::size_t i = 0; i < xu.size(); ++i) {
        const double s = 1 - xw[k];
        r.points.insert(r.points.end(), {xu[i] * (1 - xv[j]) * s, xv[j] * s, xw[k]});
        r.weights.push_back(wu[i] * wv[j] * ww[k] * (1 - xv[j]) * s * s);
      }
  return r;
}

// Adds the points of one symmetry orbit given by barycentric coordinates (a, b, b[, b]).
void addOrbit(QuadratureRule& r, double a, double b, double weight) {
  const int vertices = r.dim + 1;
  for (int v = 0; v < vertices; ++v) {
    for (int i = 1; i < vertices; ++i)
      r.points.push_back(i == v ? a : b);
    r.weights.push_back(weight);
  }
}

QuadratureRule triangleRule(int degree) {
  QuadratureRule r;
  r.dim = 2;
  if (degree <= 1) {
    r.points = {1.0 / 3, 1.0 / 3};
    r.weights = {0.5};
  } else if (degree == 2) {
    addOrbit(r, 2.0 / 3, 1.0 / 6, 1.0 / 6);
  } else if (degree <= 5) {
    // Radon (1948), degree 5.
    const double s = std::sqrt(15.0);
    r.points = {1.0 / 3, 1.0 / 3};
    r.weights = {9.0 / 80};
    const double b1 = (6 - s) / 21, b2 = (6 + s) / 21;
    addOrbit(r, 1 - 2 * b1, b1, (155 - s) / 2400);
    addOrbit(r, 1 - 2 * b2, b2, (155 + s) / 2400);
  } else {
    return collapsedRule(2, degree);
  }
  return r;
}

QuadratureRule tetrahedronRule(int degree) {
  QuadratureRule r;
  r.dim = 3;
  if (degree <= 1) {
    r.points = {0.25, 0.25, 0.25};
    r.weights = {1.0 / 6};
  } else if (degree == 2) {
    const double b = (5 - std::sqrt(5.0)) / 20;
    addOrbit(r, 1 - 3 * b, b, 1.0 / 24);
  } else {
    return collapsedRule(3, degree);
  }
  return r;
}

QuadratureRule buildRule(Shape shape, int degree) {
  switch (shape) {
    case Shape::Point: {
      QuadratureRule r;
      r.weights = {1.0};
      return r;
    }
    case Shape::Line:
      return tensorRule(1, degree);
    case Shape::Quad:
      return tensorRule(2, degree);
    case Shape::Hex:
      return tensorRule(3, degree);
    case Shape::Tri:
      return triangleRule(degree);
    case Shape::Tet:
      return tetrahedronRule(degree);
  }
  return {};
}

}  // namespace

const QuadratureRule& quadratureRule(ElementType type, int degree) {
  if (degree < 0)
    throw std::invalid_argument("quadrature degree must be >= 0, got " + std::to_string(degree));
  // std::map never moves its elements, so returned references stay valid.
  static std::map<std::pair<Shape, int>, QuadratureRule> cache;
  static std::mutex mutex;
  std::lock_guard<std::mutex> lock(mutex);
  const auto key = std::make_pair(shapeOf(type), degree);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, buildRule(key.first, degree)).first;
  return it->second;
}

int stiffnessQuadratureDegree(ElementType type) {
  const ElementTypeInfo& i = info(type);
  const Shape shape = shapeOf(type);
  // Curved tet10s need degree 3 to pass the patch test: dN/dx det J = dN/dxi cof(J) is a cubic
  // there (cof(J) is quadratic in 3D). In 2D, tri6's is a quadratic.
  if (type == ElementType::Tet10) return 3;
  if (shape == Shape::Tri || shape == Shape::Tet) return 2 * (i.order - 1);
  return 2 * i.order;
}

}  // namespace contactlab
