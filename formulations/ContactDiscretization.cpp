#include "formulations/ContactDiscretization.hpp"

#include "base/InputError.hpp"
#include "formulations/MortarDiscretization.hpp"
#include "formulations/NodeToSegmentDiscretization.hpp"
#include "formulations/ObstacleDiscretization.hpp"
#include "formulations/ObstacleMortarDiscretization.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

ContactDiscretizationRegistry& contactDiscretizationRegistry() {
  static ContactDiscretizationRegistry registry("contact discretization");
  return registry;
}

namespace {
template <class D>
ContactDiscretizationRegistry::Builder builder() {
  return [](const Teuchos::ParameterList&, const ContactZone& zone, const Mesh& mesh, int dim) {
    return std::unique_ptr<ContactDiscretization>(new D(zone, mesh, dim));
  };
}
Teuchos::RCP<const Teuchos::ParameterList> none() {
  return Teuchos::rcp(new Teuchos::ParameterList);
}
}  // namespace

void registerContactDiscretizations() {
  auto& r = contactDiscretizationRegistry();
  r.add({"node-to-segment",
         "Each slave node against the closest point of the master surface, with the smoothed "
         "normal there (the seed's collocation)",
         none, builder<NodeToSegmentDiscretization>()});
  r.add({"mortar",
         "Weighted over the slave facets: D and M integrated on the current surfaces, a point "
         "per slave node (dual or standard multiplier basis)",
         none, builder<MortarDiscretization>()});
  r.add({"rigid-obstacle",
         "Each slave node against its projection on an analytic rigid surface (plane, sphere, "
         "cylinder) that may translate",
         none, builder<ObstacleDiscretization>()});
  r.add({"rigid-obstacle-mortar",
         "Weighted over the slave facets against an analytic rigid surface: a point per slave "
         "node at the facets' D-weighted position (mortar's multiplier basis)",
         none, builder<ObstacleMortarDiscretization>()});
}

std::string discretizationName(const ContactZone& zone) {
  if (zone.obstacle)
    return zone.discretization == Discretization::mortar ? "rigid-obstacle-mortar"
                                                         : "rigid-obstacle";
  return zone.discretization == Discretization::mortar ? "mortar" : "node-to-segment";
}

std::unique_ptr<ContactDiscretization> makeContactDiscretization(const ContactZone& zone,
                                                                 const Mesh& mesh, int dim) {
  registerContactDiscretizations();
  try {
    return contactDiscretizationRegistry()
        .get(discretizationName(zone))
        .build(Teuchos::ParameterList(), zone, mesh, dim);
  } catch (const std::invalid_argument& e) {
    throw InputError("Contact/" + zone.name + ": " + e.what());
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
