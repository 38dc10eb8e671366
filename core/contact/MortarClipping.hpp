#pragma once
// Plane geometry of the 3D mortar segmentation (MortarIntegration): slave and master facets are
// projected onto the slave's auxiliary plane as polygons, which are intersected there.
//
// Polygons are vertex lists without repetition of the first vertex. Sutherland-Hodgman needs a
// convex clip polygon; the projections of valid linear facets are convex, but a warped quad seen
// at an angle may not be, so convexPieces() splits such a quad at its reflex vertex first.
#include "core/contact/ContactSearch.hpp"

#include <array>
#include <vector>

namespace contactlab {

using Point2 = std::array<double, 2>;
using Polygon2 = std::vector<Point2>;

// The plane through x0 with unit normal n0; in-plane coordinates along the orthonormal t1, t2.
struct AuxiliaryPlane {
  std::array<double, 3> x0{}, n0{}, t1{}, t2{};

  // Coordinates of the orthogonal projection of x (3 components) onto the plane.
  Point2 coordinates(const double* x) const;
};

// The facet's projection onto the plane as convex counter-clockwise polygons: a linear facet
// gives its own polygon, a quadratic one its 4 linear sub-facets through the mid-edge nodes
// (tri6: 4 triangles; quad8, quad9: 4 quads around the centre, x(0, 0) for quad8), so that
// curved facets are followed to the first order. Polygons of area <= minArea (seen edge-on)
// are left out.
std::vector<Polygon2> projectedPolygons(const Facet& facet, const AuxiliaryPlane& plane,
                                        double minArea);

// Positive for a counter-clockwise polygon.
double signedArea(const Polygon2& polygon);

// The polygon made counter-clockwise and cut into convex pieces: itself when convex, else (a
// quad with one reflex vertex) the two triangles on either side of the diagonal through that
// vertex. Throws std::invalid_argument for a self-intersecting (bow-tie) quad or a non-convex
// polygon of more than 4 vertices.
std::vector<Polygon2> convexPieces(Polygon2 polygon);

// Intersection of `subject` with the convex `clip`, both counter-clockwise (Sutherland-Hodgman).
// A vertex within `tolerance` (a length) of a clip edge counts as inside, so that coincident
// edges keep the subject's vertices instead of creating near-duplicates; vertices closer than
// `tolerance` to their predecessor are dropped. Empty or fewer than 3 vertices: no overlap.
Polygon2 clipConvex(const Polygon2& subject, const Polygon2& clip, double tolerance);

}  // namespace contactlab
