#include "core/mesh/MeshChecks.hpp"

#include <gtest/gtest.h>

namespace contactlab {
namespace {

Mesh twoTriangles() {
  Mesh m;
  m.dim = 2;
  m.source = "test.msh";
  m.coords = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  CellGroup body;
  body.name = "body";
  body.dim = 2;
  body.type = ElementType::Tri3;
  body.nodes = {0, 1, 2, 0, 3, 2};  // second one inverted: not checkMesh's business
  body.tags = {1, 2};
  m.blocks.push_back(body);
  return m;
}

std::string errorOf(const Mesh& m) {
  try {
    checkMesh(m);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(MeshChecks, AcceptsValidMeshWithInvertedElement) {
  EXPECT_NO_THROW(checkMesh(twoTriangles()));
}

TEST(MeshChecks, NodeOutOfRangeNamesGroupAndElement) {
  auto m = twoTriangles();
  m.blocks[0].nodes[4] = 7;
  EXPECT_EQ(errorOf(m),
            "mesh test.msh: block 'body' element 2 references node 7 but the mesh has 4 nodes");
}

TEST(MeshChecks, Rejects2DMeshOffPlaneAndMissingBlocks) {
  auto m = twoTriangles();
  m.coords[5] = 0.5;
  EXPECT_NE(errorOf(m).find("must lie in z = 0"), std::string::npos);
  m = twoTriangles();
  m.blocks.clear();
  EXPECT_NE(errorOf(m).find("no element block"), std::string::npos);
  m = twoTriangles();
  m.blocks[0].nodes.pop_back();
  EXPECT_NE(errorOf(m).find("connectivity entries"), std::string::npos);
  m = twoTriangles();
  m.dim = 3;
  EXPECT_NE(errorOf(m).find("dimension 2 in a 3D mesh"), std::string::npos);
}

// A node is named by its id: its gmsh tag when the mesh has tags, else its index + 1.
TEST(MeshChecks, NamesOffPlaneNodeByItsIdAndRefusesMiscountedTags) {
  auto m = twoTriangles();
  m.coords[5] = 0.5;  // node index 1
  EXPECT_NE(errorOf(m).find("node 2 has z = 0.5"), std::string::npos) << errorOf(m);
  m.nodeTags = {40, 7, 12, 3};
  EXPECT_NE(errorOf(m).find("node 7 has z = 0.5"), std::string::npos) << errorOf(m);
  m = twoTriangles();
  m.nodeTags = {40, 7, 12};
  EXPECT_EQ(errorOf(m), "mesh test.msh: has 3 node tags for 4 nodes");
}

}  // namespace
}  // namespace contactlab
