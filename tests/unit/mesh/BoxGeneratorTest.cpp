#include "MeshTestUtils.hpp"

#include "core/mesh/MeshGenerators.hpp"

#include <gtest/gtest.h>

namespace contactlab {
namespace {

struct BoxCase {
  std::string type;
  ElementType cellType;
  ElementType faceType;
  std::size_t cells;  // for 3 x 2 x 1 divisions
  std::size_t nodes;
  std::size_t zminCells;
};

void PrintTo(const BoxCase& c, std::ostream* os) {
  *os << c.type;
}

class BoxGenerator : public ::testing::TestWithParam<BoxCase> {};

TEST_P(BoxGenerator, CountsGroupsVolumeAndFaces) {
  const auto& tc = GetParam();
  BoxParams p;
  p.origin = {-1.0, 0.0, 2.0};
  p.lengths = {3.0, 1.0, 0.5};
  p.divisions = {3, 2, 1};
  p.elementType = tc.type;
  const Mesh mesh = generateBox(p);

  const test::GeneratorCase block{tc.type, tc.cellType, tc.faceType, tc.cells, tc.nodes};
  ASSERT_NO_FATAL_FAILURE(test::expectGeneratedBlock(mesh, block, 3));
  EXPECT_NEAR(test::blockMeasure(mesh, "body"), 1.5, 1e-12);

  const std::vector<std::string> names{"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  EXPECT_EQ(mesh.boundaryNames(), names);
  const double planes[6] = {-1.0, 2.0, 0.0, 1.0, 2.0, 2.5};
  for (int f = 0; f < 6; ++f) {
    const auto groups = mesh.findBoundaries(names[f]);
    ASSERT_EQ(groups.size(), 1u);
    EXPECT_EQ(groups[0]->type, tc.faceType);
    for (auto k : mesh.boundaryNodes(names[f]))
      EXPECT_NEAR(test::node(mesh, k)[f / 2], planes[f], 1e-12) << names[f];
  }
  EXPECT_EQ(mesh.findBoundaries("zmin")[0]->size(), tc.zminCells);
}

// 3 x 2 x 1: 4*3*2 = 24 corners, 46 edges, 7*5*3 = 105 points of the order-2 grid (tet10 too:
// each hex face has one diagonal and each hex one inner diagonal); hex20: 24 + 46 = 70.
INSTANTIATE_TEST_SUITE_P(
    AllTypes, BoxGenerator,
    ::testing::Values(BoxCase{"tet4", ElementType::Tet4, ElementType::Tri3, 36, 24, 12},
                      BoxCase{"tet10", ElementType::Tet10, ElementType::Tri6, 36, 105, 12},
                      BoxCase{"hex8", ElementType::Hex8, ElementType::Quad4, 6, 24, 6},
                      BoxCase{"hex20", ElementType::Hex20, ElementType::Quad8, 6, 70, 6},
                      BoxCase{"hex27", ElementType::Hex27, ElementType::Quad9, 6, 105, 6}),
    [](const auto& info) { return info.param.type; });

TEST(BoxGeneratorErrors, NameTheParameter) {
  BoxParams p;
  p.elementType = "quad4";
  EXPECT_THROW(generateBox(p), std::invalid_argument);
  p.elementType = "hex8";
  p.divisions = {1, 0, 1};
  try {
    generateBox(p);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "box generator: ny = 0 must be at least 1");
  }
}

}  // namespace
}  // namespace contactlab
