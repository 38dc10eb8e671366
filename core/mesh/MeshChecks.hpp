#pragma once
// Structural sanity checks run by the readers and generators before a Mesh is handed out.
// Element orientation is deliberately NOT checked or fixed here: an inverted element is
// reported, naming the element, by the fem module.
#include "core/mesh/Mesh.hpp"

namespace contactlab {

// Throws std::runtime_error naming the mesh source and the offending group/element when:
// dim is not 2 or 3; coords is not 3 per node or not finite; there is no block; nodeTags is
// neither empty nor one per node; a group's
// connectivity size, cell dimension (blocks: dim, boundaries: below dim) or a node index is
// invalid; a 2D mesh has a node off the plane z = 0.
void checkMesh(const Mesh& mesh);

}  // namespace contactlab
