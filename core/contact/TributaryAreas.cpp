#include "core/contact/TributaryAreas.hpp"

#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/QuadratureRule.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <algorithm>
#include <vector>

namespace contactlab {

NodePosition referencePositions(const Mesh& mesh) {
  return [&mesh](std::int64_t node) {
    return std::array<double, 3>{mesh.coords[3 * node], mesh.coords[3 * node + 1],
                                 mesh.coords[3 * node + 2]};
  };
}

std::map<std::int64_t, double> tributaryAreas(const Mesh& mesh, const std::string& group, int dim,
                                              const NodePosition& position,
                                              const SurfaceWeight& weight) {
  std::map<std::int64_t, double> weights;
  for (const CellGroup* g : mesh.findBoundaries(group)) {
    const ReferenceElement& ref = ReferenceElement::get(g->type);
    const QuadratureRule& rule = quadratureRule(g->type, 2 * info(g->type).order + 1);
    const int n = g->nodesPerCell();
    std::vector<double> x(3 * n), N(n), dN(n * ref.dim()), diag(n);
    double normal[3];
    for (std::size_t c = 0; c < g->size(); ++c) {
      for (int a = 0; a < n; ++a) {
        const auto xa = position(g->nodes[c * n + a]);
        std::copy(xa.begin(), xa.end(), x.begin() + 3 * a);
      }
      std::fill(diag.begin(), diag.end(), 0.0);
      double area = 0, sum = 0;
      for (int q = 0; q < rule.size(); ++q) {
        const double* xi = &rule.points[q * rule.dim];
        ref.shape(xi, N.data());
        ref.shapeDerivatives(xi, dN.data());
        double dA = facetGeometry(dim, n, x.data(), dN.data(), normal) * rule.weights[q];
        if (weight) {
          double point[3];
          interpolatePosition(n, x.data(), N.data(), point);
          dA *= weight(point);
        }
        area += dA;
        for (int a = 0; a < n; ++a)
          diag[a] += N[a] * N[a] * dA;
      }
      for (int a = 0; a < n; ++a)
        sum += diag[a];
      for (int a = 0; a < n; ++a)
        weights[g->nodes[c * n + a]] += area * diag[a] / sum;
    }
  }
  return weights;
}

}  // namespace contactlab
