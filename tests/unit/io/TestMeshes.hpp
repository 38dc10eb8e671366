#pragma once
// Small deterministic meshes for the writer tests, mirrored by read_vtk.py: every cell has its
// own nodes, placed at x = b + A u where u are gmsh's reference coordinates (mapped to [0,1]
// for lines, quads and hexes) and A, b depend on the global cell id. A and b are written as
// cell data so that read_vtk.py can check each VTK node against VTK's own parametric
// coordinates, which catches any gmsh → VTK node order mistake.
#include "core/io/MeshPiece.hpp"

#include <string>
#include <vector>

namespace contactlab::test {

// Cell types of the 2D and 3D test meshes (global cell g has type list[g % list.size()]).
std::vector<ElementType> planeCellTypes();
std::vector<ElementType> solidCellTypes();

// The cells g with g % size == rank of a mesh of `numCells` cells cycling through `types`,
// with point data "displacement" (2 components in 2D, 3 in 3D) and "gap", and cell data
// "von_mises", "stress" (6), "map_A" (9), "map_b" (3), "cell_id", "rank"; values depend on
// `time` as read_vtk.py expects.
MeshPiece makeTestPiece(const std::vector<ElementType>& types, int numCells, int dim, int rank,
                        int size, double time);

// Output folder shared with read_vtk.py: <CONTACTLAB_IO_TEST_OUTPUT>/np<size>/<name>.
std::string testOutputDir(const std::string& name, int size);

}  // namespace contactlab::test
