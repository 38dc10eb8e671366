// The automatic r_n = E / h: E of the softer body the contact surfaces bound, h the median
// corner edge of the slave facets (a graded surface's coarse facets do not set it).
#include "core/materials/LinearElastic.hpp"
#include "formulations/ContactScale.hpp"

#include <gtest/gtest.h>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace contactlab {
namespace {

// Two stacked blocks in 2D: 'soft' (quad4 [0, 5] x [0, 1]) under 'hard' ([0, 5] x [1, 2]).
// Boundaries: 'soft-top' (lines of lengths 1, 1, 3 at y = 1, the soft block's nodes) and
// 'hard-bottom' (one line of the hard block at y = 1, its own nodes).
Mesh twoBlocks() {
  Mesh mesh;
  mesh.dim = 2;
  const double xs[] = {0, 1, 2, 5};
  for (double y : {0.0, 1.0})  // nodes 0-3 (y = 0), 4-7 (y = 1): the soft block
    for (double x : xs)
      mesh.coords.insert(mesh.coords.end(), {x, y, 0});
  for (double y : {1.0, 2.0})  // nodes 8-9 (y = 1), 10-11 (y = 2): the hard block
    for (double x : {0.0, 5.0})
      mesh.coords.insert(mesh.coords.end(), {x, y, 0});
  CellGroup soft{"soft", 2, ElementType::Quad4, {0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6}, {1, 2, 3}};
  CellGroup hard{"hard", 2, ElementType::Quad4, {8, 9, 11, 10}, {4}};
  CellGroup top{"soft-top", 1, ElementType::Line2, {4, 5, 5, 6, 6, 7}, {5, 6, 7}};
  CellGroup bottom{"hard-bottom", 1, ElementType::Line2, {8, 9}, {8}};
  mesh.blocks = {soft, hard};
  mesh.boundaries = {top, bottom};
  return mesh;
}

std::map<std::string, std::shared_ptr<const Material>> materials(double soft, double hard) {
  return {{"soft", std::make_shared<LinearElastic>(soft, 0.3)},
          {"hard", std::make_shared<LinearElastic>(hard, 0.3)}};
}

TEST(ContactScale, SofterBodyOverMedianSlaveEdge) {
  const Mesh mesh = twoBlocks();
  const auto scale = contactScale(mesh, materials(10, 1000), "soft-top", "hard-bottom");
  EXPECT_DOUBLE_EQ(scale.youngModulus, 10.0);
  EXPECT_DOUBLE_EQ(scale.facetSize, 1.0);  // median of 1, 1, 3 (the mean would be 5/3)
  EXPECT_DOUBLE_EQ(scale.stiffness(), 10.0);
  // The softer body sets E whichever side it is on.
  EXPECT_DOUBLE_EQ(contactScale(mesh, materials(1000, 10), "soft-top", "hard-bottom").youngModulus,
                   10.0);
}

TEST(ContactScale, ObstacleCountsTheSlaveBodyOnly) {
  const Mesh mesh = twoBlocks();
  EXPECT_DOUBLE_EQ(contactScale(mesh, materials(1000, 10), "soft-top", "").youngModulus, 1000.0);
}

TEST(ContactScale, NoMaterialIsRefused) {
  const Mesh mesh = twoBlocks();
  EXPECT_THROW(contactScale(mesh, {}, "soft-top", ""), std::invalid_argument);
}

}  // namespace
}  // namespace contactlab
