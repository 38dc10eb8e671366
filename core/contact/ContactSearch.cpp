#include "core/contact/ContactSearch.hpp"

#include "core/mesh/Mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace contactlab {
namespace {

// Two candidate answers are "the same" (distance tie, same kink point) within this fraction of
// the facet size: far above the projection's convergence error, far below any element size.
constexpr double kTieTolerance = 1e-9;

double distance3(const double* a, const double* b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

}  // namespace

std::vector<Facet> facetsOf(const Mesh& mesh, const std::string& group) {
  const auto groups = mesh.findBoundaries(group);
  if (groups.empty()) {
    std::string known;
    for (const auto& name : mesh.boundaryNames())
      known += (known.empty() ? "" : ", ") + name;
    throw std::invalid_argument("facetsOf: no boundary group '" + group + "' (known: " + known +
                                ")");
  }
  std::vector<Facet> facets;
  for (const CellGroup* g : groups) {
    const int n = g->nodesPerCell();
    for (std::size_t c = 0; c < g->size(); ++c) {
      Facet f{g->type, std::vector<double>(3 * n), g->tags[c]};
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < 3; ++i)
          f.coords[3 * a + i] = mesh.coords[3 * g->nodes[c * n + a] + i];
      facets.push_back(std::move(f));
    }
  }
  return facets;
}

ContactSearch::ContactSearch(std::vector<Facet> facets, double searchDistance)
    : facets_(std::move(facets)), searchDistance_(searchDistance) {
  if (!(searchDistance >= 0.0))
    throw std::invalid_argument("ContactSearch: search distance must be >= 0");
  std::vector<double> boxes(6 * facets_.size());
  spaceDim_.resize(facets_.size());
  size_.resize(facets_.size());
  for (std::size_t f = 0; f < facets_.size(); ++f) {
    const Facet& facet = facets_[f];
    const ElementTypeInfo& ti = info(facet.type);
    if (ti.dim != 1 && ti.dim != 2)
      throw std::invalid_argument(std::string("ContactSearch: '") + ti.name +
                                  "' is not a facet type (facet " + std::to_string(f) + ")");
    if (facet.coords.size() != static_cast<std::size_t>(3 * ti.nodes))
      throw std::invalid_argument("ContactSearch: facet " + std::to_string(f) + " has " +
                                  std::to_string(facet.coords.size()) + " coordinates, expected " +
                                  std::to_string(3 * ti.nodes));
    spaceDim_[f] = ti.dim + 1;
    double* b = &boxes[6 * f];
    for (int d = 0; d < 3; ++d) {
      b[d] = std::numeric_limits<double>::infinity();
      b[3 + d] = -std::numeric_limits<double>::infinity();
    }
    for (int a = 0; a < ti.nodes; ++a)
      for (int d = 0; d < 3; ++d) {
        b[d] = std::min(b[d], facet.coords[3 * a + d]);
        b[3 + d] = std::max(b[3 + d], facet.coords[3 * a + d]);
      }
    size_[f] = std::sqrt((b[3] - b[0]) * (b[3] - b[0]) + (b[4] - b[1]) * (b[4] - b[1]) +
                         (b[5] - b[2]) * (b[5] - b[2]));
    const double inflate = ti.order > 1 ? kQuadraticInflation * size_[f] : 0.0;
    for (int d = 0; d < 3; ++d) {
      b[d] -= inflate;
      b[3 + d] += inflate;
    }
  }
  tree_ = BoundingBoxTree(std::move(boxes));
}

Pairing ContactSearch::findClosest(const double* slavePoint) const {
  Pairing result;
  std::vector<std::size_t> candidates;
  tree_.withinDistance(slavePoint, searchDistance_, candidates);
  result.candidates = static_cast<int>(candidates.size());

  std::vector<Projection> projections(candidates.size());
  std::size_t best = candidates.size();  // position in `candidates`; none yet
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const std::size_t f = candidates[k];
    projections[k] =
        projectOnFacet(facets_[f].type, spaceDim_[f], facets_[f].coords.data(), slavePoint);
    ++result.projections;
    const Projection& p = projections[k];
    if (p.distance > searchDistance_) continue;
    if (best == candidates.size()) {
      best = k;
      continue;
    }
    const Projection& q = projections[best];
    const double tie = kTieTolerance * std::max(size_[f], size_[candidates[best]]);
    const bool closer = p.distance < q.distance - tie;
    const bool tiedButInside = std::abs(p.distance - q.distance) <= tie && p.inside && !q.inside;
    if (closer || tiedButInside) best = k;
  }
  if (best == candidates.size()) return result;

  result.found = true;
  result.facet = candidates[best];
  result.projection = projections[best];
  if (result.projection.inside) return result;

  // Boundary point: average the normals of every facet reaching the same point (a kink vertex or
  // edge seen from its convex side). A lone facet edge (surface border) keeps its own normal.
  Projection& chosen = result.projection;
  const double tol = kTieTolerance * size_[result.facet];
  double normal[3] = {0.0, 0.0, 0.0};
  int shared = 0;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const Projection& p = projections[k];
    if (std::abs(p.distance - chosen.distance) > tol || distance3(p.point, chosen.point) > tol)
      continue;
    for (int i = 0; i < 3; ++i)
      normal[i] += p.normal[i];
    ++shared;
  }
  result.sharedBy = shared;
  const double norm =
      std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  // norm ~ 0 only for a folded surface (opposite facets meeting): keep the chosen facet's normal.
  if (shared < 2 || norm < 1e-12) return result;
  double side = 0.0;
  for (int i = 0; i < 3; ++i) {
    chosen.normal[i] = normal[i] / norm;
    side += (slavePoint[i] - chosen.point[i]) * chosen.normal[i];
  }
  chosen.gap = side < 0.0 ? -chosen.distance : chosen.distance;
  return result;
}

}  // namespace contactlab
