#include "formulations/MortarDiscretization.hpp"

#include "base/InputError.hpp"
#include "core/contact/MortarIntegration.hpp"
#include "core/contact/SurfaceFrames.hpp"
#include "core/contact/TributaryAreas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace contactlab {
namespace {

// The share of a node's tributary area the master must cover for the node to be paired: on
// linear slave facets any coverage counts (its gap is the nodal value of the interpolated gap,
// the dual basis being built on the covered part), on quadratic ones 1 %.
constexpr double kSliverCoverage = 1e-8, kQuadraticSliverCoverage = 1e-2;
// The largest sum of |coefficients| of a quadratic-facet node's gap: 2 to 8 where the master
// covers the node's facets (hertz-3d-two-body, tet10 and hex27).
constexpr double kMaxGapAmplification = 12.0;

}  // namespace

MortarDiscretization::MortarDiscretization(const ContactZone& zone, const Mesh& mesh, int dim)
    : ContactDiscretization(dim, resolvedSearchDistance(zone, mesh)),
      mesh_(mesh),
      zoneName_(zone.name),
      slave_(zone.slave),
      basis_(zone.multiplierBasis),
      areaWeight_(zone.areaWeight),
      master_(mesh, zone.master) {}

void MortarDiscretization::prepare(const ContactSurfaceState& state, double /*t*/) {
  const ContactSearch search(master_.currentFacets(state), searchDistance_);
  rows_ = rows(search, state);
  // Mortar integrates on the current surface, so its multiplier is a traction per current area.
  // Node-to-segment and the small-strain bulk work per reference area: scale each point's
  // weight by its facets' reference-to-current area ratio, which makes the mortar multiplier a
  // nominal pressure too (it differs from the current one by the surface strain, ~1 % in the
  // Hertz cases) and keeps a uniform pressure uniform.
  currentAreas_ = tributaryAreas(
      mesh_, slave_, dim_, [&state](std::int64_t node) { return state.position(node); },
      areaWeight_);
}

PointPairing MortarDiscretization::pair(ContactPoint& pt, const std::array<double, 3>& xs,
                                        const ContactSurfaceState& state, double /*t*/) {
  PointPairing result;
  result.size = searchDistance_ / 2;
  const auto it = rows_.find(pt.node);
  double w = 0;
  if (it != rows_.end())
    for (const auto& entry : it->second.slave)
      w += entry.second;
  // Covered by the master surface's projection. Its gap is the weighted gap over the covered
  // part divided by w: over a sliver of a quadratic facet, whose dual functions have signed
  // lobes, that is no gap (hertz-3d-two-body on hex27: a node 0.2 above the master, 5e-4 of its
  // weight covered, gap -0.083 from coefficients up to 7).
  const bool quadratic = it != rows_.end() && it->second.quadratic;
  pt.paired = w > (quadratic ? kQuadraticSliverCoverage : kSliverCoverage) * pt.referenceWeight;
  pt.self = 1.0;
  pt.weight = pt.referenceWeight;
  if (pt.paired) {
    const Row& row = it->second;
    const auto own = row.slave.find(pt.node);
    pt.self = own == row.slave.end() ? 0.0 : own->second / w;
    pt.master.clear();
    pt.N.clear();
    for (const auto& [k, d] : row.slave)
      if (k != pt.node) {
        pt.master.push_back(k);
        pt.N.push_back(-d / w);
      }
    for (const auto& [l, m] : row.master) {
      pt.master.push_back(l);
      pt.N.push_back(m / w);
    }
    pt.weight = w * pt.referenceWeight / currentAreas_.at(pt.node);
    pt.facet = couplingKey(pt.master);
    for (int c = 0; c < 3; ++c)
      pt.normal[c] = -row.normal[c];  // from the master towards the slave
    const auto xm = masterPoint(pt, xs, state);
    result.gap = pt.normal[0] * (xs[0] - xm[0]) + pt.normal[1] * (xs[1] - xm[1]) +
                 pt.normal[2] * (xs[2] - xm[2]);
    // The gap combines the nodes' positions with coefficients summing to 0; beyond
    // kMaxGapAmplification in magnitude it is no gap either (the same sphere on tet10 at Size
    // Contact 0.08: a node 1.2 % covered had 22, and the geometric fixed point cycled with
    // period 3).
    double amplification = std::abs(pt.self);
    for (double c : pt.N)
      amplification += std::abs(c);
    if (row.quadratic && amplification > kMaxGapAmplification) {
      pt.paired = false;
      pt.self = 1.0;
      pt.weight = pt.referenceWeight;
    }
  }
  return result;
}

std::map<std::int64_t, MortarDiscretization::Row> MortarDiscretization::rows(
    const ContactSearch& search, const ContactSurfaceState& state) const {
  std::vector<Facet> facets;
  std::vector<std::int64_t> facetNodes;
  for (const CellGroup* g : mesh_.findBoundaries(slave_)) {
    const int n = g->nodesPerCell();
    for (std::size_t c = 0; c < g->size(); ++c) {
      Facet f;
      f.type = g->type;
      for (int a = 0; a < n; ++a) {
        const std::int64_t node = g->nodes[c * n + a];
        facetNodes.push_back(node);
        const auto x = state.position(node);
        f.coords.insert(f.coords.end(), x.begin(), x.end());
      }
      facets.push_back(std::move(f));
    }
  }
  const auto normals = nodalNormals(facets, facetNodes);
  const int nm = master_.nodesPerFacet();
  std::map<std::int64_t, Row> rows;
  std::vector<std::size_t> candidates;
  std::size_t offset = 0;
  for (const Facet& f : facets) {
    const std::size_t n = f.coords.size() / 3;
    double box[6] = {1e300, 1e300, 1e300, -1e300, -1e300, -1e300};
    for (std::size_t a = 0; a < n; ++a)
      for (int c = 0; c < 3; ++c) {
        box[c] = std::min(box[c], f.coords[3 * a + c] - searchDistance_);
        box[3 + c] = std::max(box[3 + c], f.coords[3 * a + c] + searchDistance_);
      }
    search.tree().intersecting(box, candidates);
    std::sort(candidates.begin(), candidates.end());  // the same sums on every rank
    std::vector<const Facet*> masters;
    for (std::size_t c : candidates)
      masters.push_back(&search.facets()[c]);
    std::vector<std::array<double, 3>> slaveNormals(n);
    for (std::size_t a = 0; a < n; ++a)
      slaveNormals[a] = normals.at(facetNodes[offset + a]);
    MortarIntegrals in;
    try {
      in = integrateMortar(f, slaveNormals, masters, basis_, areaWeight_, searchDistance_);
    } catch (const std::invalid_argument& e) {
      throw InputError("Contact/" + zoneName_ + ": mortar: " + e.what());
    }
    const double tiny = 1e-14 * in.area;
    for (std::size_t j = 0; j < n; ++j) {
      Row& row = rows[facetNodes[offset + j]];
      row.normal = normals.at(facetNodes[offset + j]);
      row.quadratic = info(f.type).order > 1;
      for (std::size_t k = 0; k < n; ++k)
        if (std::abs(in.D[j * n + k]) > tiny) row.slave[facetNodes[offset + k]] += in.D[j * n + k];
      for (const MortarMaster& m : in.masters)
        for (int l = 0; l < nm; ++l)
          if (std::abs(m.M[j * nm + l]) > tiny)
            row.master[master_.node(candidates[m.facet], l)] += m.M[j * nm + l];
    }
    offset += n;
  }
  return rows;
}

}  // namespace contactlab
