// The smoothed normal's closed-form derivative against central differences of the normal it
// differentiates (nodalNormals interpolated and normalized, as node-to-segment computes it), on
// curved patches of quadratic and linear facets in 2D and 3D.
#include "core/contact/SmoothedNormalDerivative.hpp"
#include "core/contact/SurfaceFrames.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

// Facets with their mesh nodes; a node's coordinates are shared by every facet holding it.
struct Patch {
  std::vector<Facet> facets;
  std::vector<std::int64_t> nodes;  // per facet, its nodes
  std::map<std::int64_t, std::array<double, 3>> x;

  void rebuild() {
    std::size_t offset = 0;
    for (Facet& f : facets) {
      const int n = ReferenceElement::get(f.type).numNodes();
      f.coords.resize(3 * n);
      for (int a = 0; a < n; ++a)
        for (int c = 0; c < 3; ++c)
          f.coords[3 * a + c] = x.at(nodes[offset + a])[c];
      offset += n;
    }
  }
  std::array<double, 3> normal(const std::vector<std::int64_t>& at, const std::vector<double>& N) {
    rebuild();
    const auto nodal = nodalNormals(facets, nodes);
    std::array<double, 3> n{};
    for (std::size_t a = 0; a < at.size(); ++a)
      for (int c = 0; c < 3; ++c)
        n[c] += N[a] * nodal.at(at[a])[c];
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& v : n)
      v /= length;
    return n;
  }
};

// A surface z = 0.3 sin(x) cos(0.7 y) + small per-node wobble (2D: the curve y = 0.3 sin(x)).
std::array<double, 3> curved(double u, double v, int dim, std::int64_t node) {
  const double wobble = 0.01 * std::sin(3.7 * node);
  if (dim == 2) return {u + wobble, 0.3 * std::sin(u), 0.0};
  return {u + wobble, v - wobble, 0.3 * std::sin(u) * std::cos(0.7 * v)};
}

void expectMatchesDifferences(Patch& patch, int dim, ElementType type) {
  const ReferenceElement& ref = ReferenceElement::get(type);
  const int n = ref.numNodes();
  std::vector<std::int64_t> at(patch.nodes.begin(), patch.nodes.begin() + n);  // facet 0
  std::vector<double> xi(ref.dim(), 0.21), N(n);
  ref.shape(xi.data(), N.data());
  patch.rebuild();
  const auto blocks = smoothedNormalDerivative(patch.facets, patch.nodes, at, N);
  ASSERT_FALSE(blocks.empty());
  const double h = 1e-6;
  double largest = 0;
  for (auto& [node, position] : patch.x)
    for (int j = 0; j < dim; ++j) {
      const double saved = position[j];
      position[j] = saved + h;
      const auto plus = patch.normal(at, N);
      position[j] = saved - h;
      const auto minus = patch.normal(at, N);
      position[j] = saved;
      const auto it = blocks.find(node);
      for (int i = 0; i < 3; ++i) {
        const double fd = (plus[i] - minus[i]) / (2 * h);
        const double exact = it == blocks.end() ? 0.0 : it->second[i * 3 + j];
        EXPECT_NEAR(exact, fd, 1e-7) << "node " << node << " dn_" << i << "/dx_" << j;
        largest = std::max(largest, std::abs(fd));
      }
    }
  EXPECT_GT(largest, 0.1);  // the normal does turn with the nodes
}

TEST(SmoothedNormalDerivative, MatchesDifferencesOnCurvedLines) {
  for (ElementType type : {ElementType::Line2, ElementType::Line3}) {
    Patch patch;
    const int n = ReferenceElement::get(type).numNodes();
    // Three facets along the curve, node ids increasing along it (line3: its mid node last).
    for (int f = 0; f < 3; ++f) {
      Facet facet;
      facet.type = type;
      patch.facets.push_back(facet);
      patch.nodes.push_back(2 * f);
      patch.nodes.push_back(2 * f + 2);
      if (n == 3) patch.nodes.push_back(2 * f + 1);
    }
    for (std::int64_t k = 0; k <= 6; ++k)
      patch.x[k] = curved(0.4 * k - 1.0, 0.0, 2, k);
    expectMatchesDifferences(patch, 2, type);
  }
}

TEST(SmoothedNormalDerivative, MatchesDifferencesOnCurvedQuadAndTriangleFacets) {
  // quad4, quad8 and tri6: a strip of two cells on the curved surface, nodes on a grid of
  // quarter cells.
  for (ElementType type : {ElementType::Quad4, ElementType::Quad8, ElementType::Tri6}) {
    Patch patch;
    const ReferenceElement& ref = ReferenceElement::get(type);
    const int n = ref.numNodes();
    auto gridNode = [](int i, int j) { return static_cast<std::int64_t>(j * 9 + i); };
    for (int e = 0; e < 2; ++e) {
      // The facet's nodes from its reference coordinates mapped onto the grid.
      const int triangles = type == ElementType::Tri6 ? 2 : 1;
      for (int t = 0; t < triangles; ++t) {
        Facet facet;
        facet.type = type;
        patch.facets.push_back(facet);
        for (int a = 0; a < n; ++a) {
          const double r = ref.nodeCoordinates()[2 * a], s = ref.nodeCoordinates()[2 * a + 1];
          // quad: r, s in [-1, 1] over the cell [4e, 4e + 4] x [0, 4]; tri6: r, s in [0, 1], the
          // second triangle the first turned by 180 degrees (same orientation).
          const bool tri = type == ElementType::Tri6;
          const double u = tri ? (t ? 1 - r : r) : (r + 1) / 2,
                       v = tri ? (t ? 1 - s : s) : (s + 1) / 2;
          const int i = 4 * e + static_cast<int>(std::lround(4 * u));
          const int j = static_cast<int>(std::lround(4 * v));
          patch.nodes.push_back(gridNode(i, j));
        }
      }
    }
    for (std::int64_t node : patch.nodes)
      patch.x[node] = curved(0.25 * static_cast<double>(node % 9),
                             0.25 * static_cast<double>(node / 9), 3, node);
    expectMatchesDifferences(patch, 3, type);
  }
}

}  // namespace
}  // namespace contactlab
