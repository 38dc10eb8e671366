#include "core/contact/MortarClipping.hpp"

#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace contactlab {
namespace {

double cross(const Point2& a, const Point2& b, const Point2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

double distance(const Point2& a, const Point2& b) {
  return std::hypot(b[0] - a[0], b[1] - a[1]);
}

// The facet's linear sub-polygons (node lists; -1 is the centre x(0, 0) of a quad8).
const std::vector<std::vector<int>>& subPolygons(ElementType t) {
  static const std::vector<std::vector<int>> tri3{{0, 1, 2}}, quad4{{0, 1, 2, 3}},
      tri6{{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}},
      quad8{{0, 4, -1, 7}, {4, 1, 5, -1}, {-1, 5, 2, 6}, {7, -1, 6, 3}},
      quad9{{0, 4, 8, 7}, {4, 1, 5, 8}, {8, 5, 2, 6}, {7, 8, 6, 3}};
  switch (t) {
    case ElementType::Tri3:
      return tri3;
    case ElementType::Tri6:
      return tri6;
    case ElementType::Quad4:
      return quad4;
    case ElementType::Quad8:
      return quad8;
    default:
      return quad9;
  }
}

}  // namespace

Point2 AuxiliaryPlane::coordinates(const double* x) const {
  const double d[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
  return {d[0] * t1[0] + d[1] * t1[1] + d[2] * t1[2], d[0] * t2[0] + d[1] * t2[1] + d[2] * t2[2]};
}

std::vector<Polygon2> projectedPolygons(const Facet& facet, const AuxiliaryPlane& plane,
                                        double minArea) {
  double centre[3] = {0, 0, 0};
  if (facet.type == ElementType::Quad8) {
    double N[8];
    const double xi[2] = {0.0, 0.0};
    ReferenceElement::get(facet.type).shape(xi, N);
    interpolatePosition(8, facet.coords.data(), N, centre);
  }
  std::vector<Polygon2> pieces;
  for (const std::vector<int>& nodes : subPolygons(facet.type)) {
    Polygon2 polygon;
    for (int a : nodes)
      polygon.push_back(plane.coordinates(a < 0 ? centre : &facet.coords[3 * a]));
    if (std::abs(signedArea(polygon)) <= minArea) continue;
    for (Polygon2& piece : convexPieces(std::move(polygon)))
      pieces.push_back(std::move(piece));
  }
  return pieces;
}

double signedArea(const Polygon2& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0, n = polygon.size(); i < n; ++i) {
    const Point2& p = polygon[i];
    const Point2& q = polygon[(i + 1) % n];
    twice += p[0] * q[1] - p[1] * q[0];
  }
  return 0.5 * twice;
}

std::vector<Polygon2> convexPieces(Polygon2 polygon) {
  if (signedArea(polygon) < 0.0) std::reverse(polygon.begin(), polygon.end());
  const std::size_t n = polygon.size();
  std::vector<std::size_t> reflex;
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& prev = polygon[(i + n - 1) % n];
    const Point2& p = polygon[i];
    const Point2& next = polygon[(i + 1) % n];
    // Relative to the two edge lengths, so that collinear vertices (a straight quadratic edge
    // split at its mid-node) are not mistaken for reflex ones by round-off.
    if (cross(prev, p, next) < -1e-12 * distance(prev, p) * distance(p, next)) reflex.push_back(i);
  }
  if (reflex.empty()) return {polygon};
  if (n == 4 && reflex.size() == 1) {
    const std::size_t r = reflex[0];
    const Point2 &a = polygon[r], &b = polygon[(r + 1) % 4], &c = polygon[(r + 2) % 4],
                 &d = polygon[(r + 3) % 4];
    return {{a, b, c}, {a, c, d}};
  }
  throw std::invalid_argument(
      "mortar segmentation: a facet's projection on the auxiliary plane is self-intersecting "
      "(the facet is too warped or seen nearly edge-on)");
}

Polygon2 clipConvex(const Polygon2& subject, const Polygon2& clip, double tolerance) {
  Polygon2 out = subject, in;
  for (std::size_t e = 0, ne = clip.size(); e < ne && out.size() >= 3; ++e) {
    const Point2& a = clip[e];
    const Point2& b = clip[(e + 1) % ne];
    const double length = distance(a, b);
    in.swap(out);
    out.clear();
    for (std::size_t i = 0, n = in.size(); i < n; ++i) {
      const Point2& p = in[i];
      const Point2& q = in[(i + 1) % n];
      const double sp = cross(a, b, p) / length, sq = cross(a, b, q) / length;
      const bool pInside = sp >= -tolerance, qInside = sq >= -tolerance;
      if (pInside) out.push_back(p);
      if (pInside != qInside) {
        // Clamped: with the tolerance band, the inside point may lie slightly beyond the line.
        const double t = std::clamp(sp / (sp - sq), 0.0, 1.0);
        out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
      }
    }
  }
  Polygon2 result;
  for (const Point2& p : out)
    if (result.empty() || distance(result.back(), p) > tolerance) result.push_back(p);
  while (result.size() > 1 && distance(result.back(), result.front()) <= tolerance)
    result.pop_back();
  if (result.size() < 3) result.clear();
  return result;
}

}  // namespace contactlab
