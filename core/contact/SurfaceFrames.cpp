#include "core/contact/SurfaceFrames.hpp"

#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <cmath>

namespace contactlab {
namespace {

double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// t1 = the coordinate axis `axis` made orthogonal to n, t2 = n x t1.
void frameFromAxis(const std::array<double, 3>& n, int axis, std::array<double, 3>& t1,
                   std::array<double, 3>& t2) {
  std::array<double, 3> e{};
  e[axis] = 1.0;
  const double en = n[axis];
  for (int i = 0; i < 3; ++i)
    t1[i] = e[i] - en * n[i];
  const double norm = std::sqrt(dot(t1, t1));
  for (double& v : t1)
    v /= norm;
  t2 = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2], n[0] * t1[1] - n[1] * t1[0]};
}

// A kept axis while |n_axis| stays below this: t1's largest component is then still the axis it
// was built from (|n_axis| < 1/sqrt(2)), so the frame's history needs no field of its own; the
// least aligned axis is never above 1/sqrt(3).
constexpr double kKeptAxisLimit = 0.7;

}  // namespace

void tangentBasis(int dim, const std::array<double, 3>& n, std::array<double, 3>& t1,
                  std::array<double, 3>& t2) {
  if (dim == 2) {
    t1 = {-n[1], n[0], 0.0};
    t2 = {0, 0, 0};
    return;
  }
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(n[i]) < std::abs(n[axis])) axis = i;
  frameFromAxis(n, axis, t1, t2);
}

void tangentBasisFollowing(int dim, const std::array<double, 3>& n, std::array<double, 3>& t1,
                           std::array<double, 3>& t2) {
  if (dim == 3) {
    int axis = -1;
    double largest = 0;
    for (int i = 0; i < 3; ++i)
      if (std::abs(t1[i]) > largest) {
        largest = std::abs(t1[i]);
        axis = i;
      }
    if (axis >= 0 && std::abs(n[axis]) < kKeptAxisLimit) {
      frameFromAxis(n, axis, t1, t2);
      return;
    }
  }
  tangentBasis(dim, n, t1, t2);
}

std::map<std::int64_t, std::array<double, 3>> nodalNormals(
    const std::vector<Facet>& facets, const std::vector<std::int64_t>& facetNodes) {
  std::map<std::int64_t, std::array<double, 3>> normals;
  std::size_t offset = 0;
  for (const Facet& f : facets) {
    const ReferenceElement& ref = ReferenceElement::get(f.type);
    const int n = ref.numNodes(), rd = ref.dim();
    const int spaceDim = rd + 1;
    std::vector<double> dN(static_cast<std::size_t>(n) * rd);
    for (int a = 0; a < n; ++a) {
      ref.shapeDerivatives(&ref.nodeCoordinates()[a * rd], dN.data());
      double normal[3];
      facetGeometry(spaceDim, n, f.coords.data(), dN.data(), normal);
      auto& sum = normals[facetNodes[offset + a]];
      for (int c = 0; c < 3; ++c)
        sum[c] += normal[c];
    }
    offset += n;
  }
  for (auto& [node, v] : normals) {
    const double norm = std::sqrt(dot(v, v));
    for (double& c : v)
      c /= norm;
  }
  return normals;
}

}  // namespace contactlab
