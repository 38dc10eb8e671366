#pragma once
// The augmented Lagrangian's r_n when a scene leaves Normal Augmentation at 0: E / h, the scale
// its doc string recommends, from the model itself. E is the smallest Young's modulus at rest
// (referenceYoungModulus) of the blocks the zone's surfaces bound (the softer body sets the
// contact stiffness), h the median corner-to-corner edge length of the slave facets (the
// median, not the mean: a graded surface's few coarse far facets do not set it). r_n changes
// the Newton path only: the augmented Lagrangian's converged state does not depend on it.
#include "core/materials/Material.hpp"
#include "core/mesh/Mesh.hpp"

#include <map>
#include <memory>
#include <string>

namespace contactlab {

// The contact pressure, as a fraction of E, at which the automatic r_t makes the stick
// stiffness mu p r_t of the augmented friction law equal to r_n = E / h.
inline constexpr double kAutomaticContactStrain = 0.01;

struct AugmentationScale {
  double youngModulus = 0;  // E, of the softer body
  double facetSize = 0;     // h, of the slave surface
  double normalAugmentation() const { return youngModulus / facetSize; }
  // r_t when a frictional scene leaves Tangential Augmentation at 0: 1 / (0.01 mu h), i.e.
  // r_n / (mu p) at p = 1 % of E. The multiplier Lambda is a number and r_t Lambda's change per
  // unit slip: its natural scale is (E / h) / (mu p), so 1 / h (the old advice) is E / (mu p)
  // times too small wherever the contact strain p / E is small: code_aster SSNV128 (p / E =
  // 4e-4, mu = 1) failed with r_t = 1 / h under every algorithm and converges from 1e4 to 1e8
  // (1 / (0.01 h) = 8e4). Measured on the 9 frictional scenes shipped with contactlab (p / E
  // from 5e-5 to 0.05): all converge with it, in 0.75x to 2.4x the Newton iterations of their
  // hand-picked r_t; 1 / (0.001 mu h) fails 2 of them (doc/verification.md "SSNV128").
  double tangentialAugmentation(double mu) const {
    return 1.0 / (kAutomaticContactStrain * mu * facetSize);
  }
};

// For a failed run's message: a coefficient the user gave (`key` its full path, `value` > 0)
// more than a decade from the model's scale (`automatic`, what 0 would have given), and what to
// set instead; empty within a decade. The augmented Lagrangian's converged state does not depend
// on r_n and r_t, but its Newton path does: SSNV128 with mu = 1 and the r_t = 800 of its public
// model (1/100 of the scale) fails at the first step under every retry, and converges from
// 8e3 up.
std::string augmentationAdvice(const std::string& key, double value, double automatic);

// `master` empty: a rigid obstacle (only the slave's blocks count). Throws std::invalid_argument
// when no block bounded by the surfaces has a material, or the slave facets have no size.
AugmentationScale automaticAugmentation(
    const Mesh& mesh, const std::map<std::string, std::shared_ptr<const Material>>& materials,
    const std::string& slave, const std::string& master);

}  // namespace contactlab
