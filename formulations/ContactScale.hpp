#pragma once
// The scale of a contact zone's equations, from the model itself: E / h, E the smallest Young's
// modulus at rest (referenceYoungModulus) of the blocks the zone's surfaces bound (the softer
// body sets the contact stiffness), h the median corner-to-corner edge length of the slave
// facets (the median, not the mean: a graded surface's few coarse far facets do not set it).
// The formulations' automatic coefficients (FormulationRegistry: automaticCoefficients) are
// computed from it, and the contact rows' residual is measured as forces with it.
#include "core/materials/Material.hpp"
#include "core/mesh/Mesh.hpp"

#include <map>
#include <memory>
#include <string>

namespace contactlab {

struct ContactScale {
  double youngModulus = 0;  // E, of the softer body
  double facetSize = 0;     // h, of the slave surface
  double stiffness() const { return youngModulus / facetSize; }
};

// `master` empty: a rigid obstacle (only the slave's blocks count). Throws std::invalid_argument
// when no block bounded by the surfaces has a material, or the slave facets have no size.
ContactScale contactScale(const Mesh& mesh,
                          const std::map<std::string, std::shared_ptr<const Material>>& materials,
                          const std::string& slave, const std::string& master);

// For a failed run's message: a coefficient the user gave (`key` its full path, `value` > 0)
// more than a decade from the model's scale (`automatic`, what 0 would have given), and what to
// set instead; empty within a decade. The augmented Lagrangian's converged state does not depend
// on r_n and r_t, but its Newton path does: a coefficient far below the model's scale can fail
// from the first step under every retry (doc/verification.md "SSNV128").
std::string coefficientAdvice(const std::string& key, double value, double automatic);

}  // namespace contactlab
