#pragma once
// Reads gmsh .msh files (format 2.2 and 4.x, ASCII or binary) through gmsh's API, or meshes a
// gmsh .geo script.
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
// A .geo script is run and meshed in its own dimension (the highest of its entities) with its
// own Mesh options, then read the same way; `sizeFactor` scales its element sizes
// (Mesh.MeshSizeFactor) and `elementOrder` > 0 sets Mesh.ElementOrder (0: the script's), so one
// script serves a mesh-convergence study. Both must keep their defaults for a .msh file.
// Throws std::invalid_argument when the file does not exist or is neither a .msh nor a .geo
// file, or holds an element type contactlab does not support, or the options are given for a
// .msh file; std::runtime_error when gmsh cannot read or mesh it or it has no physical group of
// dimension 2 or 3.
Mesh readGmshFile(const std::string& path, double sizeFactor = 1.0, int elementOrder = 0);

}  // namespace contactlab
