#pragma once
// One contact zone of a scene: a slave surface against a master surface or a rigid obstacle,
// with a friction coefficient and a formulation (the contact law at each slave point).
#include "core/contact/MortarIntegration.hpp"
#include "core/contact/RigidObstacle.hpp"
#include "formulations/ContactLaw.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace contactlab {

// The contact statuses the first load step starts from (Code_Aster's CONTACT_INIT): the
// statuses the predictor gives (closed where the gap is <= 0), every paired point closed, or
// every point open. A starting point, not a constraint: the initial multipliers are set so that
// the first iterate has these statuses (formulations with multipliers only).
enum class InitialContact { interpenetrated, all, none };

struct ContactZone {
  std::string name;
  std::string slave;   // boundary physical group (its nodes are the contact points)
  std::string master;  // boundary physical group; empty when `obstacle` is set
  std::optional<RigidObstacleSpec> obstacle;
  double friction = 0.0;  // Coulomb mu >= 0; 0 builds no friction unknowns
  // Master facets farther than this from a slave point are not candidates; 0 = automatic
  // (twice the largest slave facet size).
  double searchDistance = 0.0;
  InitialContact initialContact = InitialContact::interpenetrated;
  // Where the contact conditions hold: a contact discretization registry name
  // (ContactDiscretizationType.hpp), e.g. node-to-segment or mortar.
  std::string discretization = "node-to-segment";
  MultiplierBasis multiplierBasis = MultiplierBasis::Dual;  // where the discretization has one
  // Boundary group of slave nodes without friction (code_aster's SANS_GROUP_NO_FR); empty:
  // none. Nodes whose tangential motion the Dirichlet conditions fix need not be listed.
  std::string noFrictionGroup;
  std::string noContactGroup;  // slave nodes left out of the zone (always open)
  // What a failed run's message adds about the user's coefficients (empty: nothing to say).
  std::string coefficientAdvice;
  std::string formulation;  // registry name, for reports
  std::shared_ptr<const ContactLaw> law;
  // The contact stiffness E / h of the zone (ContactScale.hpp; 0: unknown), the scale
  // of the multiplier rows as forces (LawOutput::normalRowForce).
  double stiffnessScale = 0.0;
  // The surfaces' measure weight (SurfaceWeight.hpp): 2 pi r in an axisymmetric model, set by
  // ContactProblem from the solid model; empty: 1.
  SurfaceWeight areaWeight;
};

}  // namespace contactlab
