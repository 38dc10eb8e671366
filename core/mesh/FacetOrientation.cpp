#include "core/mesh/FacetOrientation.hpp"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace contactlab {
namespace {

std::array<double, 3> centroid(const Mesh& mesh, const std::int64_t* nodes, int n) {
  std::array<double, 3> c{};
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < 3; ++i)
      c[i] += mesh.coords[3 * nodes[a] + i] / n;
  return c;
}

// The facet's normal from its corners, with the orientation facetGeometry gives it.
std::array<double, 3> cornerNormal(const Mesh& mesh, ElementType type, const std::int64_t* nodes) {
  const auto x = [&](int a, int i) { return mesh.coords[3 * nodes[a] + i]; };
  if (mesh.dim == 2) return {x(1, 1) - x(0, 1), -(x(1, 0) - x(0, 0)), 0.0};
  // Triangle: (x1 - x0) x (x2 - x0); quadrilateral: the diagonals (x2 - x0) x (x3 - x1).
  const bool quad = cornerCount(type) == 4;
  std::array<double, 3> a{}, b{};
  for (int i = 0; i < 3; ++i) {
    a[i] = quad ? x(2, i) - x(0, i) : x(1, i) - x(0, i);
    b[i] = quad ? x(3, i) - x(1, i) : x(2, i) - x(0, i);
  }
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

void reverseFacet(ElementType type, std::int64_t* n) {
  switch (type) {
    case ElementType::Line2:
    case ElementType::Line3:
      std::swap(n[0], n[1]);
      break;                 // a line3's mid-node stays
    case ElementType::Tri6:  // edges 0-1, 1-2, 2-0 carry mid-nodes 3, 4, 5
      std::swap(n[3], n[5]);
      [[fallthrough]];
    case ElementType::Tri3:
      std::swap(n[1], n[2]);
      break;
    case ElementType::Quad8:
    case ElementType::Quad9:  // edges 0-1 .. 3-0 carry 4 .. 7; the centre (8) stays
      std::swap(n[4], n[7]);
      std::swap(n[5], n[6]);
      [[fallthrough]];
    case ElementType::Quad4:
      std::swap(n[1], n[3]);
      break;
    default:
      break;
  }
}

std::size_t orientBoundaryFacets(Mesh& mesh) {
  // The elements around each node, through their corners.
  std::vector<std::vector<std::pair<int, std::size_t>>> around(mesh.numNodes());
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const CellGroup& g = mesh.blocks[b];
    const int k = cornerCount(g.type), per = g.nodesPerCell();
    for (std::size_t e = 0; e < g.size(); ++e)
      for (int a = 0; a < k; ++a)
        around[g.nodes[e * per + a]].emplace_back(static_cast<int>(b), e);
  }
  std::size_t turned = 0;
  for (CellGroup& f : mesh.boundaries) {
    if (f.dim != mesh.dim - 1) continue;
    const int k = cornerCount(f.type), per = f.nodesPerCell();
    for (std::size_t c = 0; c < f.size(); ++c) {
      std::int64_t* nodes = &f.nodes[c * per];
      const std::pair<int, std::size_t>* owner = nullptr;
      int owners = 0;
      for (const auto& candidate : around[nodes[0]]) {
        const CellGroup& g = mesh.blocks[candidate.first];
        const std::int64_t* en = &g.nodes[candidate.second * g.nodesPerCell()];
        const int ek = cornerCount(g.type);
        const bool holds = std::all_of(nodes + 1, nodes + k, [&](std::int64_t node) {
          return std::find(en, en + ek, node) != en + ek;
        });
        if (holds) owner = &candidate, ++owners;
      }
      if (owners != 1) continue;
      const CellGroup& g = mesh.blocks[owner->first];
      const auto inside =
          centroid(mesh, &g.nodes[owner->second * g.nodesPerCell()], cornerCount(g.type));
      const auto middle = centroid(mesh, nodes, k);
      const auto n = cornerNormal(mesh, f.type, nodes);
      double outward = 0;
      for (int i = 0; i < 3; ++i)
        outward += n[i] * (middle[i] - inside[i]);
      if (outward < 0) {
        reverseFacet(f.type, nodes);
        ++turned;
      }
    }
  }
  return turned;
}

}  // namespace contactlab
