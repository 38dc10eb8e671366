// Boundary facets are oriented outward from their element whatever the node order in the file
// (a clockwise gmsh curve reversed a pressure load before).
#include "MeshTestUtils.hpp"

#include "core/mesh/FacetOrientation.hpp"
#include "core/mesh/GmshReader.hpp"

#include <gtest/gtest.h>
#include <map>
#include <set>

namespace contactlab {
namespace {

CellGroup group(const std::string& name, int dim, ElementType type,
                std::vector<std::int64_t> nodes) {
  CellGroup g;
  g.name = name;
  g.dim = dim;
  g.type = type;
  g.nodes = std::move(nodes);
  for (std::size_t c = 0; c < g.nodes.size() / static_cast<std::size_t>(g.nodesPerCell()); ++c)
    g.tags.push_back(static_cast<std::int64_t>(c + 1));
  return g;
}

// Two unit squares side by side (nodes 0..5), with edge mid-nodes 6 (bottom of the first) and
// 7 (the shared edge).
Mesh twoSquares() {
  Mesh m;
  m.dim = 2;
  m.coords = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0, 0.5, 0, 0, 1, 0.5, 0};
  m.blocks.push_back(group("body", 2, ElementType::Quad4, {0, 1, 4, 3, 1, 2, 5, 4}));
  return m;
}

TEST(FacetOrientation, AClockwiseBoundaryLineIsTurnedOutward) {
  Mesh m = twoSquares();
  m.boundaries.push_back(group("bottom", 1, ElementType::Line2, {1, 0, 1, 2}));  // first inward
  m.boundaries.push_back(group("top", 1, ElementType::Line2, {5, 4, 3, 4}));     // second inward
  EXPECT_EQ(orientBoundaryFacets(m), 2u);
  EXPECT_EQ(m.boundaries[0].nodes, (std::vector<std::int64_t>{0, 1, 1, 2}));
  EXPECT_EQ(m.boundaries[1].nodes, (std::vector<std::int64_t>{5, 4, 4, 3}));
  EXPECT_EQ(orientBoundaryFacets(m), 0u);  // idempotent
}

TEST(FacetOrientation, ALine3KeepsItsMidNodeAndAnInterfaceKeepsItsOrder) {
  Mesh m = twoSquares();
  m.boundaries.push_back(group("bottom", 1, ElementType::Line3, {1, 0, 6}));
  m.boundaries.push_back(group("interface", 1, ElementType::Line2, {4, 1}));  // two elements
  EXPECT_EQ(orientBoundaryFacets(m), 1u);
  EXPECT_EQ(m.boundaries[0].nodes, (std::vector<std::int64_t>{0, 1, 6}));
  EXPECT_EQ(m.boundaries[1].nodes, (std::vector<std::int64_t>{4, 1}));
}

// Each mid-node still sits on the edge of the corners it sat on, and the corners' cycle is
// reversed.
void expectReversedWithMidNodes(ElementType type, int corners) {
  const int n = info(type).nodes;
  std::vector<std::int64_t> nodes(n);
  for (int a = 0; a < n; ++a)
    nodes[a] = 100 + a;
  const auto edges = [&](const std::vector<std::int64_t>& v) {
    std::map<std::int64_t, std::set<std::int64_t>> mid;
    for (int e = 0; e < corners && n > corners; ++e)
      mid[v[corners + e]] = {v[e], v[(e + 1) % corners]};
    return mid;
  };
  std::vector<std::int64_t> turned = nodes;
  reverseFacet(type, turned.data());
  EXPECT_EQ(edges(turned), edges(nodes)) << info(type).name;
  EXPECT_EQ(turned[0], nodes[0]) << info(type).name;
  EXPECT_EQ(turned[1], nodes[corners - 1]) << info(type).name;  // the cycle runs backwards
  if (type == ElementType::Quad9) {
    EXPECT_EQ(turned[8], nodes[8]);
  }
}

TEST(FacetOrientation, ReversingKeepsEveryMidNodeOnItsEdge) {
  expectReversedWithMidNodes(ElementType::Tri3, 3);
  expectReversedWithMidNodes(ElementType::Tri6, 3);
  expectReversedWithMidNodes(ElementType::Quad4, 4);
  expectReversedWithMidNodes(ElementType::Quad8, 4);
  expectReversedWithMidNodes(ElementType::Quad9, 4);
}

TEST(FacetOrientation, AQuadFaceOfACubeDrawnInwardIsTurned) {
  Mesh m;
  m.dim = 3;
  m.coords = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  m.blocks.push_back(group("body", 3, ElementType::Hex8, {0, 1, 2, 3, 4, 5, 6, 7}));
  m.boundaries.push_back(group("top", 2, ElementType::Quad4, {4, 7, 6, 5}));  // normal -z
  m.boundaries.push_back(group("bottom", 2, ElementType::Tri3, {0, 1, 2}));   // normal +z
  EXPECT_EQ(orientBoundaryFacets(m), 2u);
  EXPECT_EQ(m.boundaries[0].nodes, (std::vector<std::int64_t>{4, 5, 6, 7}));
  EXPECT_EQ(m.boundaries[1].nodes, (std::vector<std::int64_t>{0, 2, 1}));
}

// Through the reader, as a user meets it: a gmsh file whose boundary line runs clockwise.
TEST(FacetOrientation, TheGmshReaderOrientsTheFileFacets) {
  Mesh m = twoSquares();
  m.coords.resize(18);  // no mid-nodes
  m.boundaries.push_back(group("bottom", 1, ElementType::Line2, {1, 0, 2, 1}));
  const std::string dir = test::freshTempDir("facet-orientation");
  test::writeWithGmsh(m, dir + "/clockwise.msh", 4.1);
  const Mesh read = readGmshFile(dir + "/clockwise.msh");
  const CellGroup& bottom = *read.findBoundaries("bottom").at(0);
  for (std::size_t c = 0; c < bottom.size(); ++c) {
    const auto a = test::node(read, bottom.nodes[2 * c]),
               b = test::node(read, bottom.nodes[2 * c + 1]);
    EXPECT_GT(b[0], a[0]) << "facet " << c << " still runs clockwise (its normal points inward)";
  }
}

}  // namespace
}  // namespace contactlab
