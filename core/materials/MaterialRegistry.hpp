#pragma once
// The material axis: `Type: linear-elastic` plus a sibling `linear-elastic:` sublist.
#include "base/Registry.hpp"
#include "core/materials/Material.hpp"

namespace contactlab {

using MaterialRegistry = Registry<Material>;

MaterialRegistry& materialRegistry();
// Registers the materials of this module (idempotent).
void registerMaterials();

}  // namespace contactlab
