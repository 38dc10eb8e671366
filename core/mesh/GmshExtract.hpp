#pragma once
// Internal to core/mesh: turns gmsh's current model into a Mesh (used by the reader and the
// generators).
#include "core/mesh/Mesh.hpp"

#include <string>

namespace contactlab {

// Physical groups of the highest dimension (2 or 3) become blocks, lower ones boundaries; one
// CellGroup per (physical group, element type). Unnamed groups are called "<kind>-<tag>"
// (kind: point, curve, surface, volume), e.g. "surface-3". Only nodes used by cells of some
// physical group are kept, numbered 0..n-1 in increasing gmsh node tag order; with
// NodeIds::gmshTags their tags are kept in Mesh::nodeTags (a file's ids), with
// NodeIds::sequential not (a generator's nodes are known by index + 1). `source` goes to
// Mesh::source; `label` starts error messages ("mesh file 'a.msh'"). Throws
// std::runtime_error when there is no physical group or none of dimension 2 or 3, and
// std::invalid_argument for element types contactlab does not support. Runs checkMesh.
enum class NodeIds { sequential, gmshTags };
Mesh meshFromGmshModel(const std::string& source, const std::string& label,
                       NodeIds ids = NodeIds::sequential);

}  // namespace contactlab
