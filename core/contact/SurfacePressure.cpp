#include "core/contact/SurfacePressure.hpp"

#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/QuadratureRule.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <cmath>
#include <vector>

namespace contactlab {

std::map<std::int64_t, double> pressureFromNodalForces(
    const Mesh& mesh, const std::string& group, const std::map<std::int64_t, double>& forces) {
  // Surface nodes numbered 0..n-1, and the consistent mass M in rows of (column, value).
  std::map<std::int64_t, int> index;
  for (const CellGroup* g : mesh.findBoundaries(group))
    for (std::int64_t node : g->nodes)
      index.emplace(node, 0);
  int n = 0;
  for (auto& [node, i] : index)
    i = n++;
  std::vector<std::map<int, double>> M(n);
  for (const CellGroup* g : mesh.findBoundaries(group)) {
    const ReferenceElement& ref = ReferenceElement::get(g->type);
    const QuadratureRule& rule = quadratureRule(g->type, 2 * info(g->type).order + 1);
    const int k = g->nodesPerCell();
    std::vector<double> x(3 * k), N(k), dN(k * ref.dim());
    double normal[3];
    for (std::size_t c = 0; c < g->size(); ++c) {
      for (int a = 0; a < k; ++a)
        for (int i = 0; i < 3; ++i)
          x[3 * a + i] = mesh.coords[3 * g->nodes[c * k + a] + i];
      for (int q = 0; q < rule.size(); ++q) {
        const double* xi = &rule.points[q * rule.dim];
        ref.shape(xi, N.data());
        ref.shapeDerivatives(xi, dN.data());
        const double dA = facetGeometry(mesh.dim, k, x.data(), dN.data(), normal) * rule.weights[q];
        for (int a = 0; a < k; ++a)
          for (int b = 0; b < k; ++b)
            M[index[g->nodes[c * k + a]]][index[g->nodes[c * k + b]]] += N[a] * N[b] * dA;
      }
    }
  }
  std::vector<double> f(n, 0.0), p(n, 0.0), r(n), z(n), d(n), Md(n), diag(n);
  for (const auto& [node, force] : forces)
    if (auto it = index.find(node); it != index.end()) f[it->second] = force;
  for (int i = 0; i < n; ++i)
    diag[i] = M[i][i];
  const auto apply = [&](const std::vector<double>& v, std::vector<double>& out) {
    for (int i = 0; i < n; ++i) {
      out[i] = 0;
      for (const auto& [j, m] : M[i])
        out[i] += m * v[j];
    }
  };
  double fNorm = 0;
  for (double v : f)
    fNorm += v * v;
  r = f;
  for (int i = 0; i < n; ++i)
    d[i] = z[i] = r[i] / diag[i];
  double rz = 0;
  for (int i = 0; i < n; ++i)
    rz += r[i] * z[i];
  // A surface mass matrix is well conditioned (a few tens): CG converges in tens of iterations.
  for (int it = 0; it < 10 * n + 10 && rz > 0; ++it) {
    double rr = 0;
    for (double v : r)
      rr += v * v;
    if (rr <= 1e-24 * fNorm) break;
    apply(d, Md);
    double dMd = 0;
    for (int i = 0; i < n; ++i)
      dMd += d[i] * Md[i];
    const double alpha = rz / dMd;
    for (int i = 0; i < n; ++i) {
      p[i] += alpha * d[i];
      r[i] -= alpha * Md[i];
      z[i] = r[i] / diag[i];
    }
    double rzNew = 0;
    for (int i = 0; i < n; ++i)
      rzNew += r[i] * z[i];
    for (int i = 0; i < n; ++i)
      d[i] = z[i] + rzNew / rz * d[i];
    rz = rzNew;
  }
  std::map<std::int64_t, double> out;
  for (const auto& [node, force] : forces)
    if (auto it = index.find(node); it != index.end()) out[node] = p[it->second];
  return out;
}

}  // namespace contactlab
