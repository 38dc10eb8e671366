#include "TestMeshes.hpp"

#include <array>

namespace contactlab::test {
namespace {

using Coords = std::vector<std::array<double, 3>>;

// gmsh reference coordinates as printed by gmsh::model::mesh::getElementProperties (gmsh
// 4.8.4): [-1,1] for lines, quads and hexes, the unit simplex for triangles and tets.
const Coords kHex27 = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1},  {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1},
                       {1, 1, 1},    {-1, 1, 1},  {0, -1, -1}, {-1, 0, -1}, {-1, -1, 0}, {1, 0, -1},
                       {1, -1, 0},   {0, 1, -1},  {1, 1, 0},   {-1, 1, 0},  {0, -1, 1},  {-1, 0, 1},
                       {1, 0, 1},    {0, 1, 1},   {0, 0, -1},  {0, -1, 0},  {-1, 0, 0},  {1, 0, 0},
                       {0, 1, 0},    {0, 0, 1},   {0, 0, 0}};
const Coords kQuad9 = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0},  {-1, 1, 0}, {0, -1, 0},
                       {1, 0, 0},   {0, 1, 0},  {-1, 0, 0}, {0, 0, 0}};
const Coords kLine3 = {{-1, 0, 0}, {1, 0, 0}, {0, 0, 0}};
const Coords kTri6 = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0, 0}, {0.5, 0.5, 0}, {0, 0.5, 0}};
const Coords kTet10 = {{0, 0, 0},     {1, 0, 0},   {0, 1, 0},   {0, 0, 1},     {0.5, 0, 0},
                       {0.5, 0.5, 0}, {0, 0.5, 0}, {0, 0, 0.5}, {0, 0.5, 0.5}, {0.5, 0, 0.5}};

// Reference coordinates in [0,1] (VTK's parametric range); higher-order gmsh elements list the
// lower-order element's nodes first, so prefixes give the linear and serendipity types.
Coords unitCoords(ElementType type) {
  const int n = info(type).nodes;
  const int dim = info(type).dim;
  auto prefix = [n, dim](const Coords& c, bool symmetric) {
    Coords out(c.begin(), c.begin() + n);
    if (symmetric)
      for (auto& p : out)
        for (int d = 0; d < dim; ++d)
          p[d] = (p[d] + 1) / 2;
    return out;
  };
  switch (dim) {
    case 0:
      return {{0, 0, 0}};
    case 1:
      return prefix(kLine3, true);
    case 2:
      return type == ElementType::Quad4 || type == ElementType::Quad8 || type == ElementType::Quad9
                 ? prefix(kQuad9, true)
                 : prefix(kTri6, false);
    default:
      return type == ElementType::Tet4 || type == ElementType::Tet10 ? prefix(kTet10, false)
                                                                     : prefix(kHex27, true);
  }
}

// A slightly sheared, non-symmetric map per cell, so that swapped nodes land elsewhere.
std::array<double, 9> mapA(int g, int dim) {
  std::array<double, 9> a = {1.0 + 0.1 * g, 0.2, 0.1, -0.15, 0.8 + 0.05 * g, -0.2, 0.05, 0.1, 1.2};
  if (dim == 2) a[2] = a[5] = a[6] = a[7] = a[8] = 0.0;
  return a;
}

std::array<double, 3> mapB(int g, int dim) {
  return {3.0 * g, 0.5 * g, dim == 3 ? -0.25 * g : 0};
}

}  // namespace

std::vector<ElementType> planeCellTypes() {
  using ET = ElementType;
  return {ET::Point1, ET::Line2, ET::Line3, ET::Tri3, ET::Tri6, ET::Quad4, ET::Quad8, ET::Quad9};
}

std::vector<ElementType> solidCellTypes() {
  using ET = ElementType;
  return {ET::Tet4, ET::Tet10, ET::Hex8, ET::Hex20, ET::Hex27};
}

MeshPiece makeTestPiece(const std::vector<ElementType>& types, int numCells, int dim, int rank,
                        int size, double time) {
  MeshPiece piece;
  FieldData displacement{"displacement", dim, {}};
  FieldData gap{"gap", 1, {}};
  FieldData vonMises{"von_mises", 1, {}};
  FieldData stress{"stress", 6, {}};
  FieldData mapAField{"map_A", 9, {}};
  FieldData mapBField{"map_b", 3, {}};
  FieldData cellId{"cell_id", 1, {}};
  FieldData rankField{"rank", 1, {}};
  piece.offsets.push_back(0);
  for (int g = rank; g < numCells; g += size) {
    const ElementType type = types[g % types.size()];
    const auto a = mapA(g, dim);
    const auto b = mapB(g, dim);
    for (const auto& u : unitCoords(type)) {
      const auto first = static_cast<std::int64_t>(piece.numPoints());
      double x[3];
      for (int i = 0; i < 3; ++i)
        x[i] = b[i] + a[3 * i] * u[0] + a[3 * i + 1] * u[1] + a[3 * i + 2] * u[2];
      piece.points.insert(piece.points.end(), x, x + 3);
      piece.connectivity.push_back(first);
      // Mirrored in read_vtk.py: expected_displacement and expected_gap.
      const double s = 1.0 + time;
      displacement.values.push_back(s * (x[0] + 2 * x[1]));
      displacement.values.push_back(s * (3 * x[0] - x[1]));
      if (dim == 3) displacement.values.push_back(s * (x[2] - x[0]));
      gap.values.push_back(x[0] - time);
    }
    piece.cellTypes.push_back(type);
    piece.offsets.push_back(static_cast<std::int64_t>(piece.connectivity.size()));
    vonMises.values.push_back(1.5 * g + time);
    for (int k = 0; k < 6; ++k)
      stress.values.push_back(10.0 * g + k);
    mapAField.values.insert(mapAField.values.end(), a.begin(), a.end());
    mapBField.values.insert(mapBField.values.end(), b.begin(), b.end());
    cellId.values.push_back(g);
    rankField.values.push_back(rank);
  }
  piece.pointData = {displacement, gap};
  piece.cellData = {vonMises, stress, mapAField, mapBField, cellId, rankField};
  return piece;
}

std::string testOutputDir(const std::string& name, int size) {
  return std::string(CONTACTLAB_IO_TEST_OUTPUT) + "/np" + std::to_string(size) + "/" + name;
}

}  // namespace contactlab::test
