#pragma once
// What one rank hands to the result writers for one step: its points, its cells (gmsh node
// order, local point indices) and named point/cell fields. No Trilinos, no VTK types here.
#include "core/mesh/ElementType.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace contactlab {

struct FieldData {
  std::string name;
  int components = 1;
  std::vector<double> values;  // components per point (or cell), interleaved
};

struct MeshPiece {
  std::vector<double> points;              // 3 per point
  std::vector<ElementType> cellTypes;      // one per cell
  std::vector<std::int64_t> offsets;       // cell c uses connectivity[offsets[c], offsets[c+1])
  std::vector<std::int64_t> connectivity;  // local point indices, gmsh node order
  std::vector<FieldData> pointData;
  std::vector<FieldData> cellData;

  std::size_t numPoints() const { return points.size() / 3; }
  std::size_t numCells() const { return cellTypes.size(); }
};

}  // namespace contactlab
