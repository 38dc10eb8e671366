#include "formulations/MasterSurface.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace contactlab {

namespace {

// The sides of a reference facet: its end vertices (lines) or edges (corner pairs of triangles
// and quadrilaterals, gmsh order), and whether reference coordinates xi lie on side k.
struct FacetSides {
  int corners = 2;
  bool line = true;
  bool triangle = false;
};

FacetSides sidesOf(ElementType type) {
  switch (type) {
    case ElementType::Line2:
    case ElementType::Line3:
      return {2, true, false};
    case ElementType::Tri3:
    case ElementType::Tri6:
      return {3, false, true};
    default:
      return {4, false, false};  // quad4, quad8, quad9
  }
}

bool onSide(const FacetSides& f, int k, const double* xi) {
  constexpr double tol = 1e-8;
  if (f.line) return std::abs(xi[0] - (k == 0 ? -1.0 : 1.0)) <= tol;
  if (f.triangle) {
    if (k == 0) return std::abs(xi[1]) <= tol;                // corners 0-1
    if (k == 1) return std::abs(xi[0] + xi[1] - 1.0) <= tol;  // corners 1-2
    return std::abs(xi[0]) <= tol;                            // corners 2-0
  }
  static constexpr int axis[4] = {1, 0, 1, 0};
  static constexpr double value[4] = {-1.0, 1.0, 1.0, -1.0};  // corners 0-1, 1-2, 2-3, 3-0
  return std::abs(xi[axis[k]] - value[k]) <= tol;
}

}  // namespace

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

bool MasterSurface::onFreeBoundary(int facet, const double* xi) const {
  const FacetSides f = sidesOf(type_);
  const auto at = static_cast<std::size_t>(facet);
  for (int k = 0; k < f.corners; ++k) {
    if (!onSide(f, k, xi)) continue;
    // The side's corners (an end vertex is both): free when this facet alone holds them all.
    const std::vector<int>& first = nodeFacets_.at(node(at, k));
    const std::vector<int>& second = nodeFacets_.at(node(at, f.line ? k : (k + 1) % f.corners));
    const auto sharing = std::count_if(first.begin(), first.end(), [&](int g) {
      return std::find(second.begin(), second.end(), g) != second.end();
    });
    if (sharing == 1) return true;
  }
  return false;
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
