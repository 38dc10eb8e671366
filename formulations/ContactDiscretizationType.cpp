#include "formulations/ContactDiscretizationType.hpp"

#include "base/InputError.hpp"
#include "core/contact/MortarIntegration.hpp"
#include "formulations/MortarDiscretization.hpp"
#include "formulations/NodeToSegmentDiscretization.hpp"
#include "formulations/ObstacleDiscretization.hpp"
#include "formulations/ObstacleMortarDiscretization.hpp"

#include <map>
#include <stdexcept>

namespace contactlab {

std::unique_ptr<ContactDiscretization> ContactDiscretizationType::build(const ContactZone& zone,
                                                                        const Mesh& mesh,
                                                                        int dim) const {
  return zone.obstacle ? againstObstacle_(zone, mesh, dim) : againstSurface_(zone, mesh, dim);
}

std::string ContactDiscretizationType::refusal(const ContactLaw& law) const {
  if (traits_.pairsAtOnePoint || !law.hasNormalField()) return "";
  std::string accepted;
  for (const auto& other : contactDiscretizationRegistry().names())
    if (contactDiscretizationType(other).traits().pairsAtOnePoint)
      accepted += (accepted.empty() ? "" : ", ") + other;
  return law.name() + " takes the master's normal at one point, which " + name_ +
         " does not pair; use " + accepted + " (against a master surface or an obstacle)";
}

std::string ContactDiscretizationType::label(const ContactZone& zone) const {
  if (!traits_.usesMultiplierBasis) return name_;
  return name_ + (zone.multiplierBasis == MultiplierBasis::Dual ? " (dual)" : " (standard)");
}

ContactDiscretizationRegistry& contactDiscretizationRegistry() {
  static ContactDiscretizationRegistry registry("contact discretization");
  return registry;
}

namespace {

template <class D>
ContactDiscretizationType::Builder builder() {
  return [](const ContactZone& zone, const Mesh& mesh, int dim) {
    return std::unique_ptr<ContactDiscretization>(new D(zone, mesh, dim));
  };
}

ContactDiscretizationRegistry::Builder typeBuilder(std::string name,
                                                   ContactDiscretizationType::Traits traits,
                                                   ContactDiscretizationType::Builder surface,
                                                   ContactDiscretizationType::Builder obstacle) {
  return [=](const Teuchos::ParameterList&) {
    return std::make_unique<ContactDiscretizationType>(name, traits, surface, obstacle);
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
         "normal there (the seed's collocation); against an Obstacle, each slave node against its "
         "projection on the analytic surface",
         none,
         typeBuilder("node-to-segment", {true, true, false}, builder<NodeToSegmentDiscretization>(),
                     builder<ObstacleDiscretization>())});
  r.add({"mortar",
         "Weighted over the slave facets: D and M integrated on the current surfaces, a point per "
         "slave node (dual or standard multiplier basis); against an Obstacle, each slave node at "
         "its facets' D-weighted position",
         none,
         typeBuilder("mortar", {false, false, true}, builder<MortarDiscretization>(),
                     builder<ObstacleMortarDiscretization>())});
}

const ContactDiscretizationType& contactDiscretizationType(const std::string& name) {
  registerContactDiscretizations();
  static std::map<std::string, std::unique_ptr<ContactDiscretizationType>> built;
  auto it = built.find(name);
  if (it == built.end())
    it = built
             .emplace(name,
                      contactDiscretizationRegistry().get(name).build(Teuchos::ParameterList()))
             .first;
  return *it->second;
}

std::unique_ptr<ContactDiscretization> makeContactDiscretization(const ContactZone& zone,
                                                                 const Mesh& mesh, int dim) {
  try {
    return contactDiscretizationType(zone.discretization).build(zone, mesh, dim);
  } catch (const std::invalid_argument& e) {
    throw InputError("Contact/" + zone.name + ": " + e.what());
  }
}

const CellGroup* cornerlessFacets(const Mesh& mesh, const std::string& group) {
  for (const CellGroup* g : mesh.findBoundaries(group))
    if (hasTransformedBasis(g->type)) return g;
  return nullptr;
}

AutomaticDiscretization chooseAutomaticDiscretization(const Mesh& mesh, const std::string& slave,
                                                      const ContactLaw& law) {
  registerContactDiscretizations();
  const auto& names = contactDiscretizationRegistry().names();
  if (const CellGroup* g = cornerlessFacets(mesh, slave))
    for (const auto& name : names) {
      const ContactDiscretizationType& type = contactDiscretizationType(name);
      if (!type.traits().collocatesAtSlaveNodes && type.refusal(law).empty())
        return {name, std::string(info(g->type).name) + " slave facets"};
    }
  return {names.front(), ""};
}

}  // namespace contactlab
