#pragma once
// gmsh → VTK node order. contactlab keeps gmsh's order everywhere; only the VTK writer
// reorders. Tables were derived by matching reference coordinates (gmsh's
// getElementProperties against VTK's GetParametricCoords), not from memory.
#include "core/mesh/ElementType.hpp"

#include <vector>

namespace contactlab {

// order[i] is the gmsh node index that becomes VTK node i; order.size() == info(type).nodes.
// Identity for every type but tet10 (edges 1-3 and 2-3 swapped), hex20 and hex27.
const std::vector<int>& vtkNodeOrder(ElementType type);

}  // namespace contactlab
