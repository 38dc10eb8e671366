#include "core/io/VtkNodeOrder.hpp"

#include <numeric>

namespace contactlab {
namespace {

std::vector<int> identity(int n) {
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  return order;
}

std::vector<int> orderFor(ElementType type) {
  switch (type) {
    case ElementType::Tet10:
      // gmsh numbers edge 2-3 before edge 1-3; VTK the other way round.
      return {0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
    case ElementType::Hex20:
      // gmsh edges: 01 03 04 12 15 23 26 37 45 47 56 67;
      // VTK edges:  01 12 23 30 45 56 67 74 04 15 26 37.
      return {0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 13, 9, 16, 18, 19, 17, 10, 12, 14, 15};
    case ElementType::Hex27:
      // Edges as hex20; then faces, gmsh: z- y- x- x+ y+ z+, VTK: x- x+ y- y+ z- z+; centre.
      return {0,  1,  2,  3,  4,  5,  6,  7,  8,  11, 13, 9,  16, 18,
              19, 17, 10, 12, 14, 15, 22, 23, 21, 24, 20, 25, 26};
    default:
      return identity(info(type).nodes);
  }
}

std::vector<std::vector<int>> allOrders() {
  std::vector<std::vector<int>> orders;
  for (int t = 0; t <= static_cast<int>(ElementType::Hex27); ++t)
    orders.push_back(orderFor(static_cast<ElementType>(t)));
  return orders;
}

}  // namespace

const std::vector<int>& vtkNodeOrder(ElementType type) {
  static const std::vector<std::vector<int>> orders = allOrders();
  return orders.at(static_cast<std::size_t>(type));
}

}  // namespace contactlab
