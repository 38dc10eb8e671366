#pragma once
// The mesh axis: `Mesh: {Type: <type>, <type>: {...}}`, the type `file` or one of the built-in
// generators (MeshGenerators.hpp: rectangle, box, half-disc, ...). Builders take the type's
// validated sublist and the scene file's directory (relative mesh paths are relative to the
// scene).
#include "base/Registry.hpp"
#include "core/mesh/Mesh.hpp"

#include <string>

namespace contactlab {

using MeshSourceRegistry = Registry<Mesh, const std::string& /*sceneDirectory*/>;

MeshSourceRegistry& meshSourceRegistry();
void registerMeshSources();

}  // namespace contactlab
