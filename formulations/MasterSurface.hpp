#pragma once
// A zone's deformable master surface: its facets (mesh nodes, one facet type), the facets
// around each master node, and the facets at the current positions of a surface state.
#include "core/contact/ContactSearch.hpp"
#include "core/mesh/Mesh.hpp"
#include "formulations/ContactSurfaceState.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace contactlab {

class MasterSurface {
 public:
  // The facets of boundary group `group`; std::invalid_argument when there are none.
  MasterSurface(const Mesh& mesh, const std::string& group);

  ElementType type() const { return type_; }
  int nodesPerFacet() const { return nodesPerFacet_; }
  std::size_t numFacets() const { return facetNodes_.size() / nodesPerFacet_; }
  // Flat: facet f's nodes at [f * nodesPerFacet, (f + 1) * nodesPerFacet).
  const std::vector<std::int64_t>& facetNodes() const { return facetNodes_; }
  std::int64_t node(std::size_t facet, int a) const {
    return facetNodes_[facet * nodesPerFacet_ + a];
  }
  // How many facets share a master node.
  std::size_t facetsAt(std::int64_t node) const { return nodeFacets_.at(node).size(); }
  // The facets (sorted) that touch any of `nodes`.
  std::vector<int> facetsAround(const std::vector<std::int64_t>& nodes) const;

  // Whether the point of reference coordinates xi on `facet` lies on the free boundary of the
  // surface: an end vertex (2D) or an edge (3D, its corners) that no other facet of the surface
  // shares. A vertex between two facets, or an edge between two, is a kink, not a boundary.
  bool onFreeBoundary(int facet, const double* xi) const;

  Facet currentFacet(const ContactSurfaceState& state, int facet) const;
  std::vector<Facet> currentFacets(const ContactSurfaceState& state) const;

 private:
  ElementType type_ = ElementType::Point1;
  int nodesPerFacet_ = 1;
  std::vector<std::int64_t> facetNodes_;
  std::map<std::int64_t, std::vector<int>> nodeFacets_;
};

}  // namespace contactlab
