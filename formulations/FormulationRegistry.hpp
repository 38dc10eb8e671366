#pragma once
// The formulation axis: `penalty`, `lagrange`, `augmented-lagrangian`. A contact zone picks one
// with `Formulation: {Type: name, name: {parameters}}`.
#include "base/Registry.hpp"
#include "formulations/ContactLaw.hpp"
#include "formulations/ContactScale.hpp"

#include <functional>
#include <string>
#include <vector>

namespace contactlab {

using FormulationRegistry = Registry<ContactLaw>;

FormulationRegistry& formulationRegistry();

// A coefficient a formulation's parameters may leave at 0 (its default) to be computed from the
// zone's contact scale E / h. Registered with the formulation; the scene reader fills each one
// left at 0, says so in the log (`note`) and in summary.json, and for one the user gave more
// than a decade off, says what to set if the run fails (coefficientAdvice).
struct AutomaticCoefficient {
  std::string key;             // the parameter, e.g. "Normal Augmentation"
  bool needsFriction = false;  // used, hence computed, only with friction (mu > 0)
  std::function<double(const ContactScale& scale, double mu)> value;
  // The log's sentence for `value` (after "Contact/<zone>: ").
  std::function<std::string(const ContactScale& scale, double mu, double value)> note;
};

// The formulation's automatic coefficients, in the order they are computed (none: empty).
const std::vector<AutomaticCoefficient>& automaticCoefficients(const std::string& formulation);
// Registers the formulations (idempotent). Builders throw std::invalid_argument for a
// coefficient that is not > 0.
void registerFormulations();

}  // namespace contactlab
