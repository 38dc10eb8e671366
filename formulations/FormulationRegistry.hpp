#pragma once
// The formulation axis: `penalty`, `lagrange`, `augmented-lagrangian`. A contact zone picks one
// with `Formulation: {Type: name, name: {parameters}}`.
#include "base/Registry.hpp"
#include "formulations/ContactLaw.hpp"

namespace contactlab {

using FormulationRegistry = Registry<ContactLaw>;

FormulationRegistry& formulationRegistry();
// Registers the formulations (idempotent). Builders throw std::invalid_argument for a
// coefficient that is not > 0.
void registerFormulations();

}  // namespace contactlab
