#pragma once
// Static axis-aligned bounding box tree: built once per pairing update over a set of boxes, then
// queried many times (one query per slave point). Replaces the all-pairs slave x master loop of
// the contact search by O(log n + k) queries.
//
// Build: top-down, each node split at the median of the box centres along the longest axis of the
// centres' extent (std::nth_element), so the tree is balanced (depth ~ log2(n / kLeafSize)) and the
// build costs O(n log n) whatever the geometry. Nodes and traversal stacks are explicit arrays:
// no recursion, so 1e6 boxes or degenerate (all identical) boxes are no risk for the call stack.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace contactlab {

class BoundingBoxTree {
 public:
  // Boxes per leaf: small enough to prune well, large enough to keep the tree shallow.
  static constexpr std::size_t kLeafSize = 4;

  BoundingBoxTree() = default;
  // `boxes`: 6 values per box, (min x, min y, min z, max x, max y, max z).
  // Throws std::invalid_argument when the size is not a multiple of 6 or a box has min > max.
  explicit BoundingBoxTree(std::vector<double> boxes);

  std::size_t size() const { return boxes_.size() / 6; }
  const double* box(std::size_t i) const { return boxes_.data() + 6 * i; }

  // Indices of the boxes intersecting `queryBox` (6 values, touching counts), in no particular
  // order. `out` is cleared first; passing the same vector again avoids reallocation.
  void intersecting(const double* queryBox, std::vector<std::size_t>& out) const;
  // Indices of the boxes whose Euclidean distance to `point` (3 values) is <= radius (a point
  // inside a box is at distance 0). `out` is cleared first.
  void withinDistance(const double* point, double radius, std::vector<std::size_t>& out) const;

  // Squared Euclidean distance from a point to a box (0 inside).
  static double squaredDistance(const double* box, const double* point);

 private:
  struct Node {
    double box[6];        // union of the boxes below
    std::uint32_t begin;  // range [begin, end) of order_ covered by the node
    std::uint32_t end;
    std::uint32_t left;  // first child (the second is left + 1); 0 for a leaf (root is 0)
  };

  template <class Accept>
  void traverse(Accept accept, std::vector<std::size_t>& out) const;

  std::vector<double> boxes_;         // as given
  std::vector<std::uint32_t> order_;  // box indices, permuted so that every node is a range
  std::vector<Node> nodes_;           // nodes_[0] is the root (when not empty)
};

}  // namespace contactlab
