#include "formulations/MasterSurface.hpp"

#include <algorithm>
#include <stdexcept>

namespace contactlab {

MasterSurface::MasterSurface(const Mesh& mesh, const std::string& group) {
  for (const CellGroup* g : mesh.findBoundaries(group)) {
    facetNodes_.insert(facetNodes_.end(), g->nodes.begin(), g->nodes.end());
    type_ = g->type;
  }
  if (facetNodes_.empty()) throw std::invalid_argument("no boundary group '" + group + "'");
  nodesPerFacet_ = info(type_).nodes;
  for (std::size_t k = 0; k < facetNodes_.size(); ++k)
    nodeFacets_[facetNodes_[k]].push_back(static_cast<int>(k / nodesPerFacet_));
}

std::vector<int> MasterSurface::facetsAround(const std::vector<std::int64_t>& nodes) const {
  std::vector<int> facets;
  for (std::int64_t m : nodes)
    for (int f : nodeFacets_.at(m))
      facets.push_back(f);
  std::sort(facets.begin(), facets.end());
  facets.erase(std::unique(facets.begin(), facets.end()), facets.end());
  return facets;
}

Facet MasterSurface::currentFacet(const ContactSurfaceState& state, int facet) const {
  Facet f;
  f.type = type_;
  f.tag = facet;
  for (int a = 0; a < nodesPerFacet_; ++a) {
    const auto p = state.position(node(static_cast<std::size_t>(facet), a));
    f.coords.insert(f.coords.end(), p.begin(), p.end());
  }
  return f;
}

std::vector<Facet> MasterSurface::currentFacets(const ContactSurfaceState& state) const {
  std::vector<Facet> facets(numFacets());
  for (std::size_t f = 0; f < facets.size(); ++f)
    facets[f] = currentFacet(state, static_cast<int>(f));
  return facets;
}

}  // namespace contactlab
