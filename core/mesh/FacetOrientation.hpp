#pragma once
// Boundary facets oriented outward from the element they bound. A facet's normal comes from
// its node order (facetGeometry: right of the tangent in 2D, t1 x t2 in 3D), and a gmsh curve
// or surface drawn the other way round gives the opposite order: a `pressure` load would pull
// instead of push, and a contact master would face into its body (a misleading "initial
// penetration"). Every facet of a boundary group (cells of dimension dim - 1) whose corners are
// those of exactly one element is turned, if needed, so that its normal points away from that
// element's centroid. A facet between two elements (an internal interface) has no outside and
// keeps its order.
#include "core/mesh/Mesh.hpp"

#include <cstddef>

namespace contactlab {

// Returns the number of facets turned.
std::size_t orientBoundaryFacets(Mesh& mesh);

// Reverses the orientation of one facet's nodes in place (gmsh order, corners and mid-nodes).
void reverseFacet(ElementType type, std::int64_t* nodes);

}  // namespace contactlab
