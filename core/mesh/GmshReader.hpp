#pragma once
// Reads gmsh .msh files (format 2.2 and 4.x, ASCII or binary) through gmsh's API.
#include "core/mesh/Mesh.hpp"

#include <string>

namespace contactlab {

// The spatial dimension is the highest dimension of the physical groups (2 or 3): those groups
// become Mesh::blocks, lower-dimensional ones Mesh::boundaries, one CellGroup per (group,
// element type). Unnamed physical groups are called "<kind>-<tag>" with kind point, curve,
// surface or volume ("surface-1"). Only nodes used by elements of some physical group are
// kept, numbered 0..n-1 in increasing gmsh node tag order, their tags kept in Mesh::nodeTags
// (Mesh::nodeId: the ids of contact.csv and the VTK field node_id); connectivity keeps gmsh's
// node order and element orientation is not touched (inverted elements are reported by the fem
// module).
// Throws std::invalid_argument when the file does not exist or is not a .msh file, or holds an
// element type contactlab does not support; std::runtime_error when gmsh cannot read it or it
// has no physical group of dimension 2 or 3.
Mesh readGmshFile(const std::string& path);

}  // namespace contactlab
