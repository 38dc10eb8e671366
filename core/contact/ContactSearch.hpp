#pragma once
// Contact search: for a slave point, the closest point on the master surface, found among the few
// master facets a BoundingBoxTree returns near the point (no all-pairs loop), each candidate
// being resolved by projectOnFacet. Also handles the kinks between adjacent facets, which a
// single-facet projection cannot see.
//
// Candidate boxes: box of the facet's nodes. For linear facets (line2, tri3, quad4) the facet lies
// in the convex hull of its nodes (non-negative shape functions), so that box is exact. Quadratic
// facets can bulge out of it (negative shape functions, curved edges); their box is inflated by
// kQuadraticInflation x the facet size (the diagonal of its nodes' box). Heuristic: on an edge
// whose mid-side node is off the chord midpoint by d, each coordinate of the curve overshoots the
// nodes' range by less than |d|, and |d| <= a quarter of the edge length is the usual validity
// limit of quadratic elements; strongly distorted facets may still be missed near their bulge.
// A query returns the facets whose box is within the search distance of the point (Euclidean, so
// tighter than inflating the boxes by the search distance): every facet closer than the search
// distance is among them.
#include "core/contact/BoundingBoxTree.hpp"
#include "core/contact/ClosestPointProjection.hpp"
#include "core/mesh/ElementType.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace contactlab {

class Mesh;

// One master facet: type (line2/line3 in 2D, tri3/tri6/quad4/quad8/quad9 in 3D), nodal
// coordinates (3 per node, gmsh order) and the gmsh element tag (for messages).
struct Facet {
  ElementType type = ElementType::Line2;
  std::vector<double> coords;
  std::int64_t tag = -1;
};

// The facets of boundary group `group` of `mesh`, in the group's order. Throws
// std::invalid_argument naming the known boundary groups when `group` is not one.
std::vector<Facet> facetsOf(const Mesh& mesh, const std::string& group);

// Result of a search for one slave point.
struct Pairing {
  bool found = false;     // some facet lies within the search distance
  std::size_t facet = 0;  // index of the chosen facet in ContactSearch::facets()
  Projection projection;  // on that facet (normal and gap adjusted at a convex kink, see below)
  int sharedBy = 1;       // facets whose closest point is the chosen point (> 1: kink vertex/edge)
  int candidates = 0;     // facets returned by the tree for this point
  int projections = 0;    // projectOnFacet calls made for this point (== candidates)
};

class ContactSearch {
 public:
  // Facet box inflation for quadratic facets, relative to the facet size (see the file comment).
  static constexpr double kQuadraticInflation = 0.25;

  // Throws std::invalid_argument when searchDistance < 0 or a facet's coordinate count does not
  // match its type or its type is not a facet type (points, volumes).
  ContactSearch(std::vector<Facet> facets, double searchDistance);

  // Closest point of the master surface to `slavePoint` (3 components) among the facets within
  // the search distance. Choice: smallest distance; among distances equal within a relative
  // 1e-9 of the facet size, an inside projection is preferred (its normal is well defined).
  // When the winner is on a facet boundary (inside == false) and other facets reach the same
  // point (a kink, seen from its convex side), the normal is ambiguous: it is replaced by the
  // normalized average of those facets' normals at that point, and gap becomes the distance
  // signed by (x_s - point) . normal, which keeps the gap continuous across the kink.
  // Thread-safe (const, no shared scratch).
  Pairing findClosest(const double* slavePoint) const;

  const std::vector<Facet>& facets() const { return facets_; }
  // Facet f's size: the diagonal of its nodes' box (the scale of the search's tolerances).
  double facetSize(std::size_t f) const { return size_[f]; }
  double searchDistance() const { return searchDistance_; }
  const BoundingBoxTree& tree() const { return tree_; }

 private:
  std::vector<Facet> facets_;
  std::vector<int> spaceDim_;  // per facet: 2 for lines, 3 for surfaces
  std::vector<double> size_;   // per facet: diagonal of its nodes' box (tolerance scale)
  double searchDistance_ = 0.0;
  BoundingBoxTree tree_;
};

}  // namespace contactlab
