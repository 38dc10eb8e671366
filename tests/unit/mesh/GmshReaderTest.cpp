#include "MeshTestUtils.hpp"

#include "core/mesh/GmshReader.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <gtest/gtest.h>

namespace contactlab {
namespace {

void expectSameGroups(const std::vector<CellGroup>& a, const std::vector<CellGroup>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].name, b[i].name);
    EXPECT_EQ(a[i].dim, b[i].dim);
    EXPECT_EQ(a[i].type, b[i].type);
    EXPECT_EQ(a[i].nodes, b[i].nodes) << a[i].name;
    EXPECT_EQ(a[i].tags, b[i].tags) << a[i].name;
  }
}

class GmshRoundTrip : public ::testing::TestWithParam<double> {};

TEST_P(GmshRoundTrip, GeneratedMeshesReadBackIdentically) {
  const std::string dir = test::freshTempDir("roundtrip");
  RectangleParams rect;
  rect.divisions = {3, 2};
  rect.elementType = "quad9";
  StackedBlocks3DParams stacked;
  stacked.elementType = "tet10";
  stacked.lowerDivisions = {1, 1, 1};
  stacked.upperDivisions = {2, 1, 1};
  BoxParams box;
  box.divisions = {2, 1, 1};
  box.elementType = "hex20";
  int i = 0;
  for (const Mesh& mesh :
       {generateRectangle(rect), generateBox(box), generateStackedBlocks3D(stacked)}) {
    const std::string path = dir + "/mesh" + std::to_string(i++) + ".msh";
    test::writeWithGmsh(mesh, path, GetParam());
    const Mesh read = readGmshFile(path);
    EXPECT_EQ(read.source, path);
    EXPECT_EQ(read.dim, mesh.dim);
    ASSERT_EQ(read.coords.size(), mesh.coords.size());
    for (std::size_t k = 0; k < read.coords.size(); ++k)  // gmsh writes 16 digits
      EXPECT_NEAR(read.coords[k], mesh.coords[k], 1e-15 * 4);
    expectSameGroups(read.blocks, mesh.blocks);
    expectSameGroups(read.boundaries, mesh.boundaries);
  }
}

INSTANTIATE_TEST_SUITE_P(Versions, GmshRoundTrip, ::testing::Values(2.2, 4.1),
                         [](const auto& info) { return info.param < 3 ? "msh22" : "msh41"; });

const char* kHeader = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
const char* kSquareNodes = "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n9 5 5 0\n$EndNodes\n";

TEST(GmshReader, KeepsInvertedElementsNamesUnnamedGroupsAndDropsUnusedNodes) {
  const std::string path = test::freshTempDir("reader") + "/inverted.msh";
  test::writeText(path, std::string(kHeader) +
                            "$PhysicalNames\n1\n2 7 \"plate\"\n$EndPhysicalNames\n" + kSquareNodes +
                            "$Elements\n3\n10 2 2 7 1 1 2 3\n11 2 2 7 1 1 4 3\n"
                            "12 1 2 3 2 1 2\n$EndElements\n");
  const Mesh mesh = readGmshFile(path);
  EXPECT_EQ(mesh.dim, 2);
  EXPECT_EQ(mesh.numNodes(), 4u);  // node 9 is used by no element
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].name, "plate");
  EXPECT_EQ(mesh.blocks[0].tags, (std::vector<std::int64_t>{10, 11}));
  EXPECT_EQ(mesh.blocks[0].nodes, (std::vector<std::int64_t>{0, 1, 2, 0, 3, 2}));
  EXPECT_GT(test::cellMeasure(mesh, mesh.blocks[0], 0), 0.0);
  EXPECT_LT(test::cellMeasure(mesh, mesh.blocks[0], 1), 0.0);  // inverted, not "fixed"
  EXPECT_EQ(mesh.boundaryNames(), std::vector<std::string>{"curve-3"});
  EXPECT_EQ(mesh.nodeTags, (std::vector<std::int64_t>{1, 2, 3, 4}));
}

// The ids users see in gmsh are the node tags: a file whose tags are not 1..N (nor in order)
// keeps them, node i (in increasing tag order) known by its tag.
TEST(GmshReader, KeepsNonContiguousNodeTags) {
  const std::string path = test::freshTempDir("reader") + "/tags.msh";
  test::writeText(path,
                  "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
                  "$PhysicalNames\n2\n1 5 \"edge\"\n2 7 \"plate\"\n$EndPhysicalNames\n"
                  "$Entities\n0 1 1 0\n"
                  "3 0 0 0 2 0 0 1 5 0\n"
                  "1 0 0 0 2 1 0 1 7 0\n$EndEntities\n"
                  "$Nodes\n1 6 3 90\n2 1 0 6\n90\n3\n41\n17\n58\n22\n"
                  "0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n$EndNodes\n"
                  "$Elements\n2 3 1 12\n2 1 3 2\n11 90 3 58 17\n12 3 41 22 58\n"
                  "1 3 1 1\n1 90 3\n$EndElements\n");
  const Mesh mesh = readGmshFile(path);
  ASSERT_EQ(mesh.numNodes(), 6u);
  EXPECT_EQ(mesh.nodeTags, (std::vector<std::int64_t>{3, 17, 22, 41, 58, 90}));
  for (std::size_t i = 0; i < mesh.numNodes(); ++i)
    EXPECT_EQ(mesh.nodeId(static_cast<std::int64_t>(i)), mesh.nodeTags[i]);
  // Tag 90 is the node at the origin, tag 41 the one at (2, 0).
  EXPECT_EQ(test::node(mesh, 5), (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(test::node(mesh, 3), (std::array<double, 3>{2, 0, 0}));
  EXPECT_EQ(mesh.boundaryNodes("edge"), (std::vector<std::int64_t>{0, 5}));
}

// A generated mesh has no tags: its nodes are known by index + 1.
TEST(GmshReader, GeneratedMeshesNameNodesByIndexPlusOne) {
  HalfDiscParams disc;
  for (const Mesh& mesh : {generateRectangle(RectangleParams{}), generateHalfDisc(disc)}) {
    EXPECT_TRUE(mesh.nodeTags.empty()) << mesh.source;
    EXPECT_EQ(mesh.nodeId(0), 1);
    EXPECT_EQ(mesh.nodeId(static_cast<std::int64_t>(mesh.numNodes()) - 1),
              static_cast<std::int64_t>(mesh.numNodes()));
  }
}

TEST(GmshReader, MissingFile) {
  try {
    readGmshFile("no/such/mesh.msh");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "mesh file 'no/such/mesh.msh' does not exist");
  }
}

TEST(GmshReader, RejectsDirectoriesAndOtherExtensions) {
  const std::string dir = test::freshTempDir("reader-ext");
  EXPECT_THROW(readGmshFile(dir), std::invalid_argument);
  test::writeText(dir + "/mesh.vtk", "");
  try {
    readGmshFile(dir + "/mesh.vtk");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ends in neither .msh nor .geo"), std::string::npos);
  }
}

// A .geo script is meshed at load with its own options; Size Factor and Element Order override
// them, so one script serves a convergence study; they are refused for a .msh file.
TEST(GmshReader, MeshesAGeoScript) {
  const std::string dir = test::freshTempDir("reader-geo");
  test::writeText(dir + "/square.geo",
                  "Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5};\n"
                  "Point(3) = {1, 1, 0, 0.5}; Point(4) = {0, 1, 0, 0.5};\n"
                  "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                  "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                  "Transfinite Surface{1}; Recombine Surface{1};\n"
                  "Physical Surface(\"body\") = {1}; Physical Curve(\"bottom\") = {1};\n");
  const Mesh coarse = readGmshFile(dir + "/square.geo");
  EXPECT_EQ(coarse.dim, 2);
  ASSERT_EQ(coarse.blocks.size(), 1u);
  EXPECT_EQ(coarse.blocks[0].name, "body");
  EXPECT_EQ(coarse.blocks[0].type, ElementType::Quad4);
  EXPECT_EQ(coarse.blocks[0].size(), 4u);  // 2 x 2 at size 0.5
  const Mesh fine = readGmshFile(dir + "/square.geo", 0.5, 2);
  EXPECT_EQ(fine.blocks[0].size(), 16u);
  EXPECT_EQ(fine.blocks[0].type, ElementType::Quad9);
  EXPECT_EQ(fine.findBoundaries("bottom").front()->type, ElementType::Line3);
  test::writeWithGmsh(coarse, dir + "/square.msh", 4.1);
  EXPECT_THROW(readGmshFile(dir + "/square.msh", 0.5), std::invalid_argument);
  EXPECT_THROW(readGmshFile(dir + "/square.geo", -1.0), std::invalid_argument);
}

TEST(GmshReader, FileWithoutPhysicalGroups) {
  const std::string path = test::freshTempDir("reader-nophys") + "/plain.msh";
  test::writeText(
      path, std::string(kHeader) + kSquareNodes + "$Elements\n1\n1 2 2 0 1 1 2 3\n$EndElements\n");
  try {
    readGmshFile(path);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("mesh file '" + path + "' has no physical groups", 0), 0u)
        << e.what();
  }
}

TEST(GmshReader, FileWithOnlyLinePhysicalGroups) {
  const std::string path = test::freshTempDir("reader-1d") + "/lines.msh";
  test::writeText(
      path, std::string(kHeader) + kSquareNodes + "$Elements\n1\n1 1 2 4 1 1 2\n$EndElements\n");
  try {
    readGmshFile(path);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no 2D or 3D physical group"), std::string::npos);
  }
}

TEST(GmshReader, UnsupportedElementType) {
  const std::string path = test::freshTempDir("reader-prism") + "/prism.msh";
  test::writeText(path, std::string(kHeader) +
                            "$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 0 1\n6 0 1 1\n"
                            "$EndNodes\n$Elements\n1\n1 6 2 1 1 1 2 3 4 5 6\n$EndElements\n");
  try {
    readGmshFile(path);
    FAIL();
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find("gmsh element type 6 is not supported"), std::string::npos) << what;
  }
}

TEST(GmshReader, GarbageFileIsARuntimeError) {
  const std::string path = test::freshTempDir("reader-garbage") + "/garbage.msh";
  test::writeText(path, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0\n");
  EXPECT_THROW(readGmshFile(path), std::runtime_error);
}

}  // namespace
}  // namespace contactlab
