#include "core/contact/SurfacePressure.hpp"

#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/QuadratureRule.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace contactlab {
namespace {

// Conjugate gradients with a diagonal preconditioner on the sparse symmetric positive definite
// M (rows of column -> value), to 1e-12 relative. A surface mass matrix is well conditioned (a
// few tens): tens of iterations.
std::vector<double> solveMass(const std::vector<std::map<int, double>>& M,
                              const std::vector<double>& g) {
  const int n = static_cast<int>(M.size());
  std::vector<double> p(n, 0.0), r = g, z(n), d(n), Md(n), diag(n);
  for (int i = 0; i < n; ++i)
    diag[i] = M[i].at(i);
  double gNorm = 0;
  for (double v : g)
    gNorm += v * v;
  for (int i = 0; i < n; ++i)
    d[i] = z[i] = r[i] / diag[i];
  double rz = 0;
  for (int i = 0; i < n; ++i)
    rz += r[i] * z[i];
  for (int it = 0; it < 10 * n + 10 && rz > 0; ++it) {
    double rr = 0;
    for (double v : r)
      rr += v * v;
    if (rr <= 1e-24 * gNorm) break;
    for (int i = 0; i < n; ++i) {
      Md[i] = 0;
      for (const auto& [j, m] : M[i])
        Md[i] += m * d[j];
    }
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
  return p;
}

}  // namespace

SurfaceProjection::SurfaceProjection(const Mesh& mesh, const std::string& group,
                                     const SurfaceWeight& weight) {
  const std::vector<const CellGroup*> facets = mesh.findBoundaries(group);
  // The vertices numbered 0..n-1.
  std::map<std::int64_t, int> vertex;
  for (const CellGroup* g : facets)
    for (std::size_t c = 0; c < g->size(); ++c)
      for (int a = 0; a < cornerCount(g->type); ++a)
        vertex.emplace(g->nodes[c * g->nodesPerCell() + a], 0);
  int n = 0;
  for (auto& [node, k] : vertex)
    k = n++;
  M1_.resize(n);
  for (const CellGroup* g : facets) {
    if (info(g->type).dim != mesh.dim - 1)
      throw std::invalid_argument(std::string("surface pressure: '") + info(g->type).name +
                                  "' is not a facet type");
    // On lines (2D: axisymmetric rings) the lumped mass, p_k = g_k / sum_l M1_kl: still exact for
    // a uniform traction, and it does not ring where the pressure drops to 0 over one facet at the
    // zone's edge (the consistent M1 gave 0, 43, 0, 3 past a peak of 600 on the NAFEMS punch).
    lines_ = lines_ && info(g->type).dim == 1;
    const ReferenceElement& ref = ReferenceElement::get(g->type);
    const ReferenceElement& linear = ReferenceElement::get(info(g->type).linear);
    const QuadratureRule& rule = quadratureRule(g->type, 2 * info(g->type).order + 1);
    const int k = g->nodesPerCell(), corners = linear.numNodes(), dim = ref.dim();
    std::vector<double> x(3 * k), N(k), dN(k * dim), phi(corners);
    double normal[3];
    for (std::size_t c = 0; c < g->size(); ++c) {
      const std::int64_t* nodes = &g->nodes[c * k];
      for (int a = 0; a < k; ++a) {
        for (int i = 0; i < 3; ++i)
          x[3 * a + i] = mesh.coords[3 * nodes[a] + i];
        if (hats_.count(nodes[a])) continue;
        linear.shape(&ref.nodeCoordinates()[a * dim], phi.data());
        auto& hat = hats_[nodes[a]];
        for (int b = 0; b < corners; ++b)
          if (std::abs(phi[b]) > 1e-12) hat.emplace_back(vertex.at(nodes[b]), phi[b]);
      }
      for (int q = 0; q < rule.size(); ++q) {
        const double* xi = &rule.points[q * rule.dim];
        ref.shapeDerivatives(xi, dN.data());
        linear.shape(xi, phi.data());
        double dA = facetGeometry(mesh.dim, k, x.data(), dN.data(), normal) * rule.weights[q];
        if (weight) {
          ref.shape(xi, N.data());
          double xq[3];
          interpolatePosition(k, x.data(), N.data(), xq);
          dA *= weight(xq);
        }
        for (int a = 0; a < corners; ++a)
          for (int b = 0; b < corners; ++b)
            M1_[vertex.at(nodes[a])][vertex.at(nodes[b])] += phi[a] * phi[b] * dA;
      }
    }
  }
}

std::map<std::int64_t, double> SurfaceProjection::field(
    const std::map<std::int64_t, double>& forces) const {
  const int n = static_cast<int>(M1_.size());
  std::vector<double> g(n, 0.0);
  for (const auto& [node, force] : forces)
    if (auto it = hats_.find(node); it != hats_.end())
      for (const auto& [k, value] : it->second)
        g[k] += value * force;
  std::vector<double> p;
  if (lines_) {
    p.assign(n, 0.0);
    for (int k = 0; k < n; ++k) {
      double sum = 0.0;
      for (const auto& [l, value] : M1_[k])
        sum += value;
      p[k] = sum > 0 ? g[k] / sum : 0.0;
    }
  } else {
    p = solveMass(M1_, g);
  }
  std::map<std::int64_t, double> out;
  for (const auto& [node, force] : forces)
    if (auto it = hats_.find(node); it != hats_.end()) {
      double value = 0;
      for (const auto& [k, weight] : it->second)
        value += weight * p[k];
      out[node] = value;
    }
  return out;
}

std::map<std::int64_t, double> pressureFromNodalForces(const Mesh& mesh, const std::string& group,
                                                       const std::map<std::int64_t, double>& forces,
                                                       const SurfaceWeight& weight) {
  return SurfaceProjection(mesh, group, weight).field(forces);
}

}  // namespace contactlab
