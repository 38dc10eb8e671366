#pragma once
// Contact zones for the formulation tests: each formulation with coefficients of the order of
// E / h for the unit block of E = 1000 (penalty two decades stiffer), and that block's bottom
// on the rigid plane y = 0.
#include "formulations/ContactZone.hpp"
#include "formulations/FormulationRegistry.hpp"

#include <memory>
#include <string>

namespace contactlab::test {

inline std::shared_ptr<const ContactLaw> law(const std::string& name) {
  registerFormulations();
  Teuchos::ParameterList p = *formulationRegistry().get(name).validParameters();
  if (name == "penalty") p.set("Normal Penalty", 1e7), p.set("Tangential Penalty", 1e5);
  if (name == "augmented-lagrangian" || name == "normal-field-augmented-lagrangian")
    p.set("Normal Augmentation", 1e4), p.set("Tangential Augmentation", 10.0);
  if (name == "lagrange")
    p.set("Normal Complementarity Constant", 1e4),
        p.set("Tangential Complementarity Constant", 10.0);
  return formulationRegistry().get(name).build(p);
}

// The block's side 'bottom' on the plane y = 0 with friction mu, under `formulation`.
inline ContactZone floorZone(double mu, const std::string& formulation) {
  ContactZone zone;
  zone.name = "floor";
  zone.slave = "bottom";
  RigidObstacleSpec plane;
  plane.direction = {0, 1, 0};
  zone.obstacle = plane;
  zone.friction = mu;
  zone.law = test::law(formulation);
  return zone;
}

}  // namespace contactlab::test
