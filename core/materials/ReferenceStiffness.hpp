#pragma once
// A material's Young's modulus (and Poisson ratio) at its reference state (no strain, its reference
// temperature), read from its own tangent there: the stiffness scale of automatic coefficients (the
// augmented Lagrangian's r_n ~ E / h). Every law of contactlab is isotropic at rest, where its
// tangent is lambda (1 x 1) + 2 mu I; E = mu (3 lambda + 2 mu) / (lambda + mu).
#include "core/materials/Material.hpp"

namespace contactlab {

// Throws std::invalid_argument when the law cannot be evaluated at rest or its tangent there is
// not that of a stable isotropic solid (mu <= 0 or lambda + 2 mu / 3 <= 0).
double referenceYoungModulus(const Material& material);
// Its Poisson ratio there, nu = lambda / (2 (lambda + mu)); the same refusals.
double referencePoissonRatio(const Material& material);

}  // namespace contactlab
