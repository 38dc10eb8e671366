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

struct AugmentationScale {
  double youngModulus = 0;  // E, of the softer body
  double facetSize = 0;     // h, of the slave surface
  double normalAugmentation() const { return youngModulus / facetSize; }
};

// `master` empty: a rigid obstacle (only the slave's blocks count). Throws std::invalid_argument
// when no block bounded by the surfaces has a material, or the slave facets have no size.
AugmentationScale automaticAugmentation(
    const Mesh& mesh, const std::map<std::string, std::shared_ptr<const Material>>& materials,
    const std::string& slave, const std::string& master);

}  // namespace contactlab
