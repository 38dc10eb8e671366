#pragma once
// The mesh axis: `Mesh: {Type: file | rectangle | box | half-disc | half-sphere |
// stacked-blocks-2d | stacked-blocks-3d, <type>: {...}}`. Builders take the type's validated
// sublist and the scene file's directory (relative mesh paths are relative to the scene).
#include "base/Registry.hpp"
#include "core/mesh/Mesh.hpp"

#include <string>

namespace contactlab {

using MeshSourceRegistry = Registry<Mesh, const std::string& /*sceneDirectory*/>;

MeshSourceRegistry& meshSourceRegistry();
void registerMeshSources();

}  // namespace contactlab
