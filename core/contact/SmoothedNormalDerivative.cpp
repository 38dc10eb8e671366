#include "core/contact/SmoothedNormalDerivative.hpp"

#include "core/fem/ReferenceElement.hpp"
#include "core/materials/Tensor3.hpp"

#include <algorithm>
#include <cmath>

namespace contactlab {
namespace {

using tensor3::Mat3;
using tensor3::multiply;
using Vec3 = std::array<double, 3>;

double norm(const Vec3& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// (I - v v^T) / length, for a unit v.
Mat3 projector(const Vec3& v, double length) {
  Mat3 p{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      p[i * 3 + j] = ((i == j ? 1.0 : 0.0) - v[i] * v[j]) / length;
  return p;
}

// [v]x: the matrix of w -> v x w.
Mat3 cross(const Vec3& v) {
  return {0, -v[2], v[1], v[2], 0, -v[0], -v[1], v[0], 0};
}

// One facet seen from one of its nodes: the unnormalized normal nu there, the tangents and the
// shape derivatives it came from.
struct FacetAtNode {
  Vec3 nu{}, t1{}, t2{};
  std::vector<double> dN;  // numNodes x refDim
};

FacetAtNode facetAtNode(const Facet& f, int node) {
  const ReferenceElement& ref = ReferenceElement::get(f.type);
  const int n = ref.numNodes(), rd = ref.dim();
  FacetAtNode s;
  s.dN.resize(static_cast<std::size_t>(n) * rd);
  ref.shapeDerivatives(&ref.nodeCoordinates()[node * rd], s.dN.data());
  for (int b = 0; b < n; ++b)
    for (int i = 0; i < 3; ++i) {
      s.t1[i] += s.dN[b * rd] * f.coords[3 * b + i];
      if (rd == 2) s.t2[i] += s.dN[b * rd + 1] * f.coords[3 * b + i];
    }
  if (rd == 1)
    s.nu = {s.t1[1], -s.t1[0], 0.0};
  else
    s.nu = {s.t1[1] * s.t2[2] - s.t1[2] * s.t2[1], s.t1[2] * s.t2[0] - s.t1[0] * s.t2[2],
            s.t1[0] * s.t2[1] - s.t1[1] * s.t2[0]};
  return s;
}

// dnu/dx_b of that facet at that node.
Mat3 normalDerivative(const FacetAtNode& s, int b, int refDim) {
  if (refDim == 1) {
    const double d = s.dN[b];
    return {0, d, 0, -d, 0, 0, 0, 0, 0};
  }
  // nu = t1 x t2: d nu = dN_b,1 (dx x t2) + dN_b,2 (t1 x dx) = (-dN_b,1 [t2]x + dN_b,2 [t1]x) dx.
  const Mat3 a = cross(s.t2), c = cross(s.t1);
  Mat3 m{};
  for (int k = 0; k < 9; ++k)
    m[k] = -s.dN[b * 2] * a[k] + s.dN[b * 2 + 1] * c[k];
  return m;
}

}  // namespace

std::map<std::int64_t, std::array<double, 9>> smoothedNormalDerivative(
    const std::vector<Facet>& facets, const std::vector<std::int64_t>& facetNodes,
    const std::vector<std::int64_t>& pointNodes, const std::vector<double>& N) {
  // The facets at each of the point's nodes, and the nodal sums s_a.
  struct Incidence {
    std::size_t facet, offset;
    FacetAtNode at;
  };
  std::vector<std::vector<Incidence>> around(pointNodes.size());
  std::vector<Vec3> sums(pointNodes.size(), Vec3{});
  std::size_t offset = 0;
  for (std::size_t f = 0; f < facets.size(); ++f) {
    const int n = ReferenceElement::get(facets[f].type).numNodes();
    for (int a = 0; a < n; ++a) {
      const auto it = std::find(pointNodes.begin(), pointNodes.end(), facetNodes[offset + a]);
      if (it == pointNodes.end()) continue;
      const std::size_t i = static_cast<std::size_t>(it - pointNodes.begin());
      Incidence inc{f, offset, facetAtNode(facets[f], a)};
      const double length = norm(inc.at.nu);
      for (int c = 0; c < 3; ++c)
        sums[i][c] += inc.at.nu[c] / length;
      around[i].push_back(std::move(inc));
    }
    offset += n;
  }
  Vec3 interpolated{};
  std::vector<Vec3> nodal(pointNodes.size());
  for (std::size_t i = 0; i < pointNodes.size(); ++i) {
    const double length = norm(sums[i]);
    for (int c = 0; c < 3; ++c) {
      nodal[i][c] = sums[i][c] / length;
      interpolated[c] += N[i] * nodal[i][c];
    }
  }
  std::map<std::int64_t, std::array<double, 9>> blocks;
  const double length = norm(interpolated);
  if (!(length > 0)) return blocks;
  const Vec3 n{interpolated[0] / length, interpolated[1] / length, interpolated[2] / length};
  const Mat3 outer = projector(n, length);
  for (std::size_t i = 0; i < pointNodes.size(); ++i) {
    Mat3 chain = multiply(outer, projector(nodal[i], norm(sums[i])));
    for (double& v : chain)
      v *= N[i];
    for (const Incidence& inc : around[i]) {
      const Facet& facet = facets[inc.facet];
      const ReferenceElement& ref = ReferenceElement::get(facet.type);
      const double nuLength = norm(inc.at.nu);
      const Vec3 m{inc.at.nu[0] / nuLength, inc.at.nu[1] / nuLength, inc.at.nu[2] / nuLength};
      const Mat3 toFacet = multiply(chain, projector(m, nuLength));
      for (int b = 0; b < ref.numNodes(); ++b) {
        const Mat3 d = multiply(toFacet, normalDerivative(inc.at, b, ref.dim()));
        auto& block = blocks[facetNodes[inc.offset + b]];
        for (int k = 0; k < 9; ++k)
          block[k] += d[k];
      }
    }
  }
  return blocks;
}

}  // namespace contactlab
