#pragma once
// The whole mesh, as read or generated: every rank holds a copy (contact surfaces and
// partitioning need the global picture; 600 000 dofs is ~200 000 nodes, a few tens of MB).
// Nodes are numbered 0..numNodes()-1; connectivity uses those indices in gmsh node order.
// Users know a node by its id (nodeId): the gmsh node tag of a mesh read from a .msh file,
// index + 1 for a generated mesh.
#include "core/mesh/ElementType.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace contactlab {

// Cells of one type belonging to one named physical group. A physical group holding several
// element types becomes several CellGroups with the same name.
struct CellGroup {
  std::string name;  // physical group name ("body", "bottom", ...)
  int dim = 0;       // topological dimension of the cells
  ElementType type = ElementType::Point1;
  std::vector<std::int64_t> nodes;  // flat connectivity, info(type).nodes per cell
  std::vector<std::int64_t> tags;   // gmsh element tags, one per cell (for messages)

  std::size_t size() const { return tags.size(); }
  int nodesPerCell() const { return info(type).nodes; }
};

class Mesh {
 public:
  int dim = 0;                        // spatial dimension of the model: 2 or 3
  std::vector<double> coords;         // 3 per node (z = 0 in 2D)
  std::vector<CellGroup> blocks;      // cells of dimension `dim` (element blocks)
  std::vector<CellGroup> boundaries;  // cells of lower dimension (facets, edges, points)
  std::string source;                 // file name or generator description, for messages
  // The gmsh node tag of each node of a mesh read from a file; empty for a generated mesh.
  std::vector<std::int64_t> nodeTags;

  std::size_t numNodes() const { return coords.size() / 3; }
  std::size_t numElements() const;
  // The id a user knows node `node` by (outputs, messages): its gmsh tag, else node + 1.
  std::int64_t nodeId(std::int64_t node) const {
    return nodeTags.empty() ? node + 1 : nodeTags[static_cast<std::size_t>(node)];
  }

  // Groups with that name, among blocks or boundaries. Empty if none.
  std::vector<const CellGroup*> findBlocks(const std::string& name) const;
  std::vector<const CellGroup*> findBoundaries(const std::string& name) const;
  // Sorted unique node indices of a boundary group; throws std::invalid_argument naming the
  // known boundary groups when `name` is not one.
  std::vector<std::int64_t> boundaryNodes(const std::string& name) const;
  std::vector<std::string> blockNames() const;
  std::vector<std::string> boundaryNames() const;
};

}  // namespace contactlab
