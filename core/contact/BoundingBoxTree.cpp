#include "core/contact/BoundingBoxTree.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace contactlab {
namespace {

// A balanced tree over < 2^32 boxes is at most ~32 levels deep; the depth-first stack holds at
// most depth + 1 entries, so this fixed bound is never reached and no allocation is needed.
constexpr std::size_t kMaxStack = 128;

double centre(const double* box, int axis) {
  return 0.5 * (box[axis] + box[3 + axis]);
}

}  // namespace

BoundingBoxTree::BoundingBoxTree(std::vector<double> boxes) : boxes_(std::move(boxes)) {
  if (boxes_.size() % 6 != 0)
    throw std::invalid_argument("BoundingBoxTree: box array size is not a multiple of 6");
  const std::size_t n = size();
  if (n >= std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("BoundingBoxTree: too many boxes");
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d)
      if (!(box(i)[d] <= box(i)[3 + d]))
        throw std::invalid_argument("BoundingBoxTree: box " + std::to_string(i) +
                                    " has min > max (or NaN)");
  if (n == 0) return;
  order_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    order_[i] = static_cast<std::uint32_t>(i);
  nodes_.reserve(2 * (n / kLeafSize) + 1);
  nodes_.push_back(Node{{}, 0, static_cast<std::uint32_t>(n), 0});

  // Nodes are processed in creation order (a queue over nodes_ itself): each is finalized, then
  // split into two new nodes appended at the end, until only small leaves remain.
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const std::uint32_t begin = nodes_[k].begin, end = nodes_[k].end;
    double bounds[6], lo[3], hi[3];
    for (int d = 0; d < 3; ++d) {
      bounds[d] = lo[d] = std::numeric_limits<double>::infinity();
      bounds[3 + d] = hi[d] = -std::numeric_limits<double>::infinity();
    }
    for (std::uint32_t i = begin; i < end; ++i) {
      const double* b = box(order_[i]);
      for (int d = 0; d < 3; ++d) {
        bounds[d] = std::min(bounds[d], b[d]);
        bounds[3 + d] = std::max(bounds[3 + d], b[3 + d]);
        lo[d] = std::min(lo[d], centre(b, d));
        hi[d] = std::max(hi[d], centre(b, d));
      }
    }
    std::copy(bounds, bounds + 6, nodes_[k].box);
    if (end - begin <= kLeafSize) continue;
    int axis = 0;
    for (int d = 1; d < 3; ++d)
      if (hi[d] - lo[d] > hi[axis] - lo[axis]) axis = d;
    // Median split by count (not by position): balanced even when centres coincide.
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) {
                       return centre(box(a), axis) < centre(box(b), axis);
                     });
    nodes_[k].left = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back(Node{{}, begin, mid, 0});
    nodes_.push_back(Node{{}, mid, end, 0});
  }
}

double BoundingBoxTree::squaredDistance(const double* box, const double* point) {
  double s = 0.0;
  for (int d = 0; d < 3; ++d) {
    const double e = std::max({box[d] - point[d], point[d] - box[3 + d], 0.0});
    s += e * e;
  }
  return s;
}

template <class Accept>
void BoundingBoxTree::traverse(Accept accept, std::vector<std::size_t>& out) const {
  out.clear();
  if (nodes_.empty()) return;
  std::uint32_t stack[kMaxStack];
  std::size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!accept(node.box)) continue;
    if (node.left == 0) {
      for (std::uint32_t i = node.begin; i < node.end; ++i)
        if (accept(box(order_[i]))) out.push_back(order_[i]);
    } else {
      stack[top++] = node.left;
      stack[top++] = node.left + 1;
    }
  }
}

void BoundingBoxTree::intersecting(const double* queryBox, std::vector<std::size_t>& out) const {
  traverse(
      [queryBox](const double* b) {
        for (int d = 0; d < 3; ++d)
          if (b[d] > queryBox[3 + d] || b[3 + d] < queryBox[d]) return false;
        return true;
      },
      out);
}

void BoundingBoxTree::withinDistance(const double* point, double radius,
                                     std::vector<std::size_t>& out) const {
  const double r2 = radius * radius;
  traverse([point, r2](const double* b) { return squaredDistance(b, point) <= r2; }, out);
}

}  // namespace contactlab
