#pragma once
// Geometry measures and a gmsh writer used by the mesh tests only.
#include "core/mesh/Mesh.hpp"

#include <array>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace contactlab::test {

// Signed area (2D) or volume (3D) of cell `c` of `g`, from its corner nodes (bilinear /
// trilinear map for quads / hexes, exact for straight-sided cells).
double cellMeasure(const Mesh& mesh, const CellGroup& g, std::size_t c);
// Smallest signed Jacobian determinant at the corner-map Gauss points (negative: inverted).
double minCornerJacobian(const Mesh& mesh, const CellGroup& g, std::size_t c);

// Sum of cellMeasure over every block called `name`.
double blockMeasure(const Mesh& mesh, const std::string& name);
// Smallest minCornerJacobian over all blocks.
double minJacobian(const Mesh& mesh);

std::array<double, 3> node(const Mesh& mesh, std::int64_t n);
std::set<std::int64_t> blockNodes(const Mesh& mesh, const std::string& name);
std::size_t cellCount(const std::vector<const CellGroup*>& groups);

// One element type of a parameterized generator test: the cell and facet types it makes and
// the cell and node counts expected for the test's divisions.
struct GeneratorCase {
  std::string type;
  ElementType cellType;
  ElementType lineType;
  std::size_t cells;
  std::size_t nodes;
};
inline void PrintTo(const GeneratorCase& c, std::ostream* os) {
  *os << c.type;
}
// tri3, tri6, quad4, quad8, quad9 on a structured grid of `quads` cells (triangles: two per
// cell) with `linearNodes` grid points at order 1, `serendipityNodes` for quad8 and
// `completeNodes` for tri6 and quad9.
std::vector<GeneratorCase> generatorCases2D(std::size_t quads, std::size_t linearNodes,
                                            std::size_t serendipityNodes,
                                            std::size_t completeNodes);

// Expects a mesh of dimension dim with one block "body" of c.cellType, c's node and cell counts
// and no inverted cell (gtest EXPECTs; an ASSERT on the block count).
void expectGeneratedBlock(const Mesh& mesh, const GeneratorCase& c, int dim = 2);
// Expects coordinate `component` of every node of boundary group `group` to be `value` (1e-12).
void expectCoordinate(const Mesh& mesh, const std::string& group, int component, double value);

// Writes `mesh` through gmsh's API ("2.2" or "4.1"), one discrete entity and one physical
// group per CellGroup; node i gets tag i + 1, cells keep their tags.
void writeWithGmsh(const Mesh& mesh, const std::string& path, double version);

// A fresh empty directory under the system temp directory.
std::string freshTempDir(const std::string& name);

// Writes `text` to `path`.
void writeText(const std::string& path, const std::string& text);

}  // namespace contactlab::test
