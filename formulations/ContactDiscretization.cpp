#include "formulations/ContactDiscretization.hpp"

#include <algorithm>
#include <cmath>

namespace contactlab {

std::array<double, 3> ContactDiscretization::masterPoint(const ContactPoint& pt,
                                                         const std::array<double, 3>& xs,
                                                         const ContactSurfaceState& state) const {
  std::array<double, 3> xm{};
  for (int c = 0; c < 3; ++c)
    xm[c] = (1.0 - pt.self) * xs[c];
  for (std::size_t a = 0; a < pt.master.size(); ++a) {
    const auto x = state.position(pt.master[a]);
    for (int c = 0; c < 3; ++c)
      xm[c] += pt.N[a] * x[c];
  }
  return xm;
}

void ContactDiscretization::subtractMasterSide(const ContactPoint& pt,
                                               const ContactSurfaceState& state, double /*t*/,
                                               double /*tConverged*/,
                                               std::array<double, 3>& relative,
                                               std::array<double, 3>& slip) const {
  for (std::size_t a = 0; a < pt.master.size(); ++a) {
    const auto xm = state.position(pt.master[a]);
    const auto um = state.displacement(pt.master[a], false);
    const auto umc = state.displacement(pt.master[a], true);
    for (int c = 0; c < 3; ++c) {
      relative[c] -= pt.N[a] * xm[c];
      slip[c] -= pt.N[a] * (um[c] - umc[c]);
    }
  }
}

int couplingKey(const std::vector<std::int64_t>& nodes) {
  std::uint32_t hash = 2166136261u;
  for (std::int64_t node : nodes)
    hash = (hash ^ static_cast<std::uint32_t>(node)) * 16777619u;
  return static_cast<int>(hash & 0x3fffffffu);
}

double resolvedSearchDistance(const ContactZone& zone, const Mesh& mesh) {
  if (zone.searchDistance > 0) return zone.searchDistance;
  double largest = 0;
  for (const CellGroup* g : mesh.findBoundaries(zone.slave)) {
    const int n = g->nodesPerCell();
    for (std::size_t c = 0; c < g->size(); ++c) {
      std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < 3; ++i) {
          lo[i] = std::min(lo[i], mesh.coords[3 * g->nodes[c * n + a] + i]);
          hi[i] = std::max(hi[i], mesh.coords[3 * g->nodes[c * n + a] + i]);
        }
      largest =
          std::max(largest, std::sqrt(std::pow(hi[0] - lo[0], 2) + std::pow(hi[1] - lo[1], 2) +
                                      std::pow(hi[2] - lo[2], 2)));
    }
  }
  return 2.0 * largest;
}

}  // namespace contactlab
