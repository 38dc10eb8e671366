#pragma once
// The contact discretization axis (a zone's `Discretization`): a registry of types, each naming
// where a zone's contact conditions hold and building the zone's ContactDiscretization against
// its master surface or its rigid obstacle. Code that needs to know something about a zone's
// discretization asks its type (contactDiscretizationType(zone.discretization)), never its name.
// `automatic` (the scene's default) is not an entry: chooseAutomaticDiscretization picks one from
// the slave facets and the formulation, and says why.
#include "base/Registry.hpp"
#include "core/mesh/Mesh.hpp"
#include "formulations/ContactDiscretization.hpp"
#include "formulations/ContactLaw.hpp"
#include "formulations/ContactZone.hpp"

#include <functional>
#include <memory>
#include <string>

namespace contactlab {

class ContactDiscretizationType {
 public:
  using Builder =
      std::function<std::unique_ptr<ContactDiscretization>(const ContactZone&, const Mesh&, int)>;
  // What the rest of the pipeline may rely on.
  struct Traits {
    // Each point's force is its slave node's own (collocation): f / w is a nodal value there.
    // False where the points' forces are integrals over the slave facets (mortar's D).
    bool collocatesAtSlaveNodes = true;
    // Whether the normal-field formulation's n(u), the master's normal at one point, exists.
    bool pairsAtOnePoint = true;
    // Whether the zone's Multiplier Basis (dual or standard) is used.
    bool usesMultiplierBasis = false;
  };

  ContactDiscretizationType(std::string name, Traits traits, Builder againstSurface,
                            Builder againstObstacle)
      : name_(std::move(name)),
        traits_(traits),
        againstSurface_(std::move(againstSurface)),
        againstObstacle_(std::move(againstObstacle)) {}

  const std::string& name() const { return name_; }
  const Traits& traits() const { return traits_; }
  // The zone's discretization: against its obstacle when it has one, else its master surface.
  std::unique_ptr<ContactDiscretization> build(const ContactZone& zone, const Mesh& mesh,
                                               int dim) const;
  // Why `law` cannot run on this discretization (a sentence naming what can); empty when it can.
  std::string refusal(const ContactLaw& law) const;
  // The zone's discretization as reports name it (the multiplier basis where it has one).
  std::string label(const ContactZone& zone) const;

 private:
  std::string name_;
  Traits traits_;
  Builder againstSurface_;
  Builder againstObstacle_;
};

using ContactDiscretizationRegistry = Registry<ContactDiscretizationType>;
ContactDiscretizationRegistry& contactDiscretizationRegistry();
void registerContactDiscretizations();

// The registry's entry `name` (built once); std::invalid_argument naming the valid choices.
const ContactDiscretizationType& contactDiscretizationType(const std::string& name);
// The zone's discretization, built through its type (InputError for a missing group or name).
std::unique_ptr<ContactDiscretization> makeContactDiscretization(const ContactZone& zone,
                                                                 const Mesh& mesh, int dim);

// The first facet group of `group` whose corners carry no share of a smooth pressure (tri6,
// quad8: hasTransformedBasis), or null.
const CellGroup* cornerlessFacets(const Mesh& mesh, const std::string& group);

// What `automatic` picks, and why (empty when it is the registry's first entry, the default):
// on slave facets whose corners carry no share of a smooth pressure (tri6, quad8) collocation at
// the slave nodes is not sound (a uniform pressure against a plane does not come out uniform:
// doc/verification.md "Mortar against an obstacle, the default on tri6 and quad8 facets"), so
// the first registered type that integrates over the facets and runs `law`; elsewhere the first
// registered type.
struct AutomaticDiscretization {
  std::string name;
  std::string reason;
};
AutomaticDiscretization chooseAutomaticDiscretization(const Mesh& mesh, const std::string& slave,
                                                      const ContactLaw& law);

}  // namespace contactlab
