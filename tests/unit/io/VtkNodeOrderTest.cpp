#include "core/io/VtkNodeOrder.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <numeric>

namespace contactlab {
namespace {

// The tables themselves are checked against VTK's parametric coordinates by read_vtk.py; here
// only their shape: each is a permutation of the element's nodes.
TEST(VtkNodeOrder, EveryTypeIsAPermutation) {
  for (int t = 0; t <= static_cast<int>(ElementType::Hex27); ++t) {
    const auto type = static_cast<ElementType>(t);
    auto order = vtkNodeOrder(type);
    ASSERT_EQ(static_cast<int>(order.size()), info(type).nodes) << info(type).name;
    std::sort(order.begin(), order.end());
    std::vector<int> expected(order.size());
    std::iota(expected.begin(), expected.end(), 0);
    EXPECT_EQ(order, expected) << info(type).name;
  }
}

TEST(VtkNodeOrder, KnownDifferences) {
  EXPECT_EQ(vtkNodeOrder(ElementType::Tet10), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 9, 8}));
  // VTK's second edge 1-2 is gmsh's edge number 3 (node 11).
  EXPECT_EQ(vtkNodeOrder(ElementType::Hex20)[9], 11);
  EXPECT_EQ(vtkNodeOrder(ElementType::Hex27)[20], 22);  // x-min face first in VTK
  EXPECT_EQ(vtkNodeOrder(ElementType::Hex27)[26], 26);  // centre last in both
  const auto& quad9 = vtkNodeOrder(ElementType::Quad9);
  EXPECT_TRUE(std::is_sorted(quad9.begin(), quad9.end()));
}

}  // namespace
}  // namespace contactlab
