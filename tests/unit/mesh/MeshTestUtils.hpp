#pragma once
// Geometry measures and a gmsh writer used by the mesh tests only.
#include "core/mesh/Mesh.hpp"

#include <array>
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

// Writes `mesh` through gmsh's API ("2.2" or "4.1"), one discrete entity and one physical
// group per CellGroup; node i gets tag i + 1, cells keep their tags.
void writeWithGmsh(const Mesh& mesh, const std::string& path, double version);

// A fresh empty directory under the system temp directory.
std::string freshTempDir(const std::string& name);

// Writes `text` to `path`.
void writeText(const std::string& path, const std::string& text);

}  // namespace contactlab::test
