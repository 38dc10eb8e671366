#include "formulations/NodeToSegmentDiscretization.hpp"

#include "core/contact/ClosestPointProjection.hpp"
#include "core/contact/SmoothedNormalDerivative.hpp"
#include "core/contact/SurfaceFrames.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <algorithm>
#include <cmath>

namespace contactlab {

namespace {

// A slave point whose closest master point is on the master surface's free boundary (an end
// in 2D, an edge no other facet shares in 3D) and which lies off that boundary along the
// surface, farther than kBeyondEdgeTolerance of the facet, faces no master. Paired with the
// boundary, its gap (along the normal there) is its distance to the facet's extension: a slave
// surface that continues the master's line (a block standing on a longer slave) was closed
// there, its force applied at the boundary, a distance away (a couple). Within the tolerance it
// stays paired: a slave node at the master's end, moved along it by round-off or a small strain.
constexpr double kBeyondEdgeTolerance = 0.05;

// The distance of xs from `point` across `normal` (in the surface's tangent plane).
double offsetAlongSurface(const std::array<double, 3>& xs, const Projection& p) {
  double v2 = 0, vn = 0;
  for (int c = 0; c < 3; ++c) {
    const double v = xs[c] - p.point[c];
    v2 += v * v;
    vn += v * p.normal[c];
  }
  return std::sqrt(std::max(0.0, v2 - vn * vn));
}

}  // namespace

NodeToSegmentDiscretization::NodeToSegmentDiscretization(const ContactZone& zone, const Mesh& mesh,
                                                         int dim)
    : ContactDiscretization(dim, resolvedSearchDistance(zone, mesh)), master_(mesh, zone.master) {}

void NodeToSegmentDiscretization::prepare(const ContactSurfaceState& state, double /*t*/) {
  search_ = std::make_unique<ContactSearch>(master_.currentFacets(state), searchDistance_);
  nodalNormals_ = nodalNormals(search_->facets(), master_.facetNodes());
}

PointPairing NodeToSegmentDiscretization::pair(ContactPoint& pt, const std::array<double, 3>& xs,
                                               const ContactSurfaceState& /*state*/, double /*t*/) {
  PointPairing result;
  result.size = searchDistance_ / 2;
  const ElementType type = master_.type();
  const int nn = master_.nodesPerFacet();
  Pairing pairing = search_->findClosest(xs.data());
  // Hysteresis: at a vertex shared by two facets (equal distances) keep the previous facet, so
  // that the pairing, the graph and the solver's analysis do not flip-flop.
  if (pairing.found && pt.paired && pt.facet >= 0 &&
      pairing.facet != static_cast<std::size_t>(pt.facet)) {
    const Projection kept = projectOnFacet(type, dim_ == 2 ? 2 : 3,
                                           search_->facets()[pt.facet].coords.data(), xs.data());
    if (kept.converged && kept.distance <= pairing.projection.distance + 1e-9 * searchDistance_) {
      // Same point (a shared vertex or edge): keep the facet, its local coordinates, and the
      // search's normal and gap (averaged over the facets at a kink).
      pairing.facet = static_cast<std::size_t>(pt.facet);
      pairing.projection.xi[0] = kept.xi[0];
      pairing.projection.xi[1] = kept.xi[1];
    }
  }
  if (pairing.found) {
    result.size = search_->facetSize(pairing.facet);
    if (!pairing.projection.inside &&
        master_.onFreeBoundary(static_cast<int>(pairing.facet), pairing.projection.xi) &&
        offsetAlongSurface(xs, pairing.projection) > kBeyondEdgeTolerance * result.size)
      pairing.found = false;
  }
  pt.paired = pairing.found;
  if (!pt.paired) return result;
  pt.facet = static_cast<int>(pairing.facet);
  pt.master.assign(master_.facetNodes().begin() + pt.facet * nn,
                   master_.facetNodes().begin() + (pt.facet + 1) * nn);
  pt.N.resize(nn);
  ReferenceElement::get(type).shape(pairing.projection.xi, pt.N.data());
  pt.xi[0] = pairing.projection.xi[0];
  pt.xi[1] = pairing.projection.xi[1];
  pt.normal = smoothedNormal(pt, nodalNormals_, pairing.projection.normal);
  for (int c = 0; c < 3; ++c)
    result.gap += pt.normal[c] * (xs[c] - pairing.projection.point[c]);
  result.size = search_->facetSize(static_cast<std::size_t>(pt.facet));
  return result;
}

std::array<double, 3> NodeToSegmentDiscretization::smoothedNormal(
    const ContactPoint& pt, const std::map<std::int64_t, std::array<double, 3>>& nodal,
    const double* facetNormal) const {
  // Smoothed normal (Code_Aster's LISSAGE): the nodal normals interpolated at the master point,
  // continuous across the kinks of the deformed master surface, where the facet normal jumps
  // and the geometric fixed point would flip between facets.
  std::array<double, 3> n{};
  for (std::size_t a = 0; a < pt.master.size(); ++a)
    for (int c = 0; c < 3; ++c)
      n[c] += pt.N[a] * nodal.at(pt.master[a])[c];
  const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  std::array<double, 3> normal{};
  for (int c = 0; c < 3; ++c)
    normal[c] = norm > 0 ? n[c] / norm : facetNormal[c];
  return normal;
}

std::vector<std::int64_t> NodeToSegmentDiscretization::normalNodes(const ContactPoint& pt) const {
  std::vector<std::int64_t> around;
  for (int f : master_.facetsAround(pt.master))
    for (int a = 0; a < master_.nodesPerFacet(); ++a)
      around.push_back(master_.node(static_cast<std::size_t>(f), a));
  std::sort(around.begin(), around.end());
  around.erase(std::unique(around.begin(), around.end()), around.end());
  return around;
}

void NodeToSegmentDiscretization::facetsAround(const ContactPoint& pt,
                                               const ContactSurfaceState& state,
                                               std::vector<Facet>& facets,
                                               std::vector<std::int64_t>& facetNodes) const {
  facets.clear();
  facetNodes.clear();
  for (int f : master_.facetsAround(pt.master)) {
    facets.push_back(master_.currentFacet(state, f));
    for (int a = 0; a < master_.nodesPerFacet(); ++a)
      facetNodes.push_back(master_.node(static_cast<std::size_t>(f), a));
  }
}

std::map<std::int64_t, std::array<double, 3>> NodeToSegmentDiscretization::nodalNormalsAround(
    const ContactPoint& pt, const ContactSurfaceState& state) const {
  std::vector<Facet> around;
  std::vector<std::int64_t> aroundNodes;
  facetsAround(pt, state, around, aroundNodes);
  return nodalNormals(around, aroundNodes);
}

std::array<double, 3> NodeToSegmentDiscretization::currentNormal(const ContactPoint& pt,
                                                                 const ContactSurfaceState& state,
                                                                 double /*t*/) const {
  if (!pt.paired) return pt.normal;
  return smoothedNormal(pt, nodalNormalsAround(pt, state), pt.normal.data());
}

bool NodeToSegmentDiscretization::currentNormalDerivative(
    const ContactPoint& pt, const ContactSurfaceState& state, double /*t*/,
    std::map<std::int64_t, std::array<double, 9>>& blocks) const {
  blocks.clear();
  if (!pt.paired) return true;  // currentNormal is the frozen pt.normal
  std::vector<Facet> around;
  std::vector<std::int64_t> aroundNodes;
  facetsAround(pt, state, around, aroundNodes);
  const std::vector<double> N(pt.N.begin(), pt.N.begin() + pt.master.size());
  blocks = smoothedNormalDerivative(around, aroundNodes, pt.master, N);
  return !blocks.empty();  // a vanishing interpolated normal falls back to differences
}

void NodeToSegmentDiscretization::refreshGeometry(ContactPoint& pt,
                                                  const ContactSurfaceState& state, double /*t*/,
                                                  GeometricTerms terms) const {
  // The same computation as pair() on the point's facet: projection, shape values, nodal
  // normals of the facets around its nodes, interpolated and normalized.
  const auto xs = state.position(pt.node);
  const ElementType type = master_.type();
  const Facet own = master_.currentFacet(state, pt.facet);
  // At a 2D vertex shared with the next facet the pairing moves on to that facet, which to
  // first order is this facet's extension: its smooth branch gives that side's derivative. At
  // the master surface's outer end (and in 3D, on facet boundaries) the clamped projection is
  // what the residual does.
  const int space = dim_ == 2 ? 2 : 3;
  bool sharedVertex = false;
  if (dim_ == 2 && std::abs(pt.xi[0]) >= 1.0 - 1e-10) {
    const std::int64_t vertex = pt.master[pt.xi[0] < 0 ? 0 : 1];
    sharedVertex = master_.facetsAt(vertex) > 1;
  }
  Projection proj;
  if (sharedVertex)
    proj = projectOnFacetExtension(type, space, own.coords.data(), xs.data(), pt.xi);
  if (!sharedVertex || !proj.converged)
    proj = projectOnFacet(type, space, own.coords.data(), xs.data());
  ReferenceElement::get(type).shape(proj.xi, pt.N.data());
  // `pairing`: the smoothed normal (and its tangents) is held, only the master point moves.
  if (terms != GeometricTerms::full) return;
  pt.normal = smoothedNormal(pt, nodalNormalsAround(pt, state), proj.normal);
  tangentBasisFollowing(dim_, pt.normal, pt.t1, pt.t2);
}

}  // namespace contactlab
