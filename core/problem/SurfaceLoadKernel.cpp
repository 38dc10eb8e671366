#include "core/problem/SurfaceLoadKernel.hpp"

#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace contactlab {

SurfaceLoadKernel::SurfaceLoadKernel(ElementType facetType, int spaceDim, int quadratureDegree,
                                     bool axisymmetric)
    : type_(facetType),
      spaceDim_(spaceDim),
      numNodes_(info(facetType).nodes),
      axisymmetric_(axisymmetric) {
  if (axisymmetric && spaceDim != 2)
    throw std::invalid_argument("SurfaceLoadKernel: axisymmetric facets are lines in 2D");
  const int facetDim = info(facetType).dim;
  if ((facetDim != 1 && facetDim != 2) || spaceDim != facetDim + 1)
    throw std::invalid_argument(std::string("SurfaceLoadKernel: ") + info(facetType).name +
                                " is not a facet in " + std::to_string(spaceDim) +
                                "D (use line2/line3 in 2D, tri3/tri6/quad4/quad8/quad9 in 3D)");
  const int degree = quadratureDegree < 0 ? 2 * info(facetType).order + 1 : quadratureDegree;
  rule_ = &quadratureRule(facetType, degree);
  const ReferenceElement& ref = ReferenceElement::get(facetType);
  const int refDim = spaceDim_ - 1, nq = rule_->size();
  N_.resize(nq * numNodes_);
  dNdxi_.resize(nq * numNodes_ * refDim);
  for (int q = 0; q < nq; ++q) {
    const double* xi = &rule_->points[q * refDim];
    ref.shape(xi, &N_[q * numNodes_]);
    ref.shapeDerivatives(xi, &dNdxi_[q * numNodes_ * refDim]);
  }
}

template <class Visit>
void SurfaceLoadKernel::forEachPoint(const double* x, Visit&& visit) const {
  const int refDim = spaceDim_ - 1;
  for (int q = 0; q < rule_->size(); ++q) {
    double normal[3], point[3];
    const double dA =
        facetGeometry(spaceDim_, numNodes_, x, &dNdxi_[q * numNodes_ * refDim], normal);
    interpolatePosition(numNodes_, x, &N_[q * numNodes_], point);
    visit(q, point, normal, rule_->weights[q] * dA * (axisymmetric_ ? 2.0 * M_PI * point[0] : 1.0));
  }
}

double SurfaceLoadKernel::area(const double* x) const {
  double a = 0.0;
  forEachPoint(x, [&](int, const double*, const double*, double w) { a += w; });
  return a;
}

void SurfaceLoadKernel::traction(const double* x, const double* t, double* f) const {
  traction(
      x, [&](const double*, double* value) { std::copy(t, t + spaceDim_, value); }, f);
}

void SurfaceLoadKernel::traction(const double* x,
                                 const std::function<void(const double* x, double* t)>& t,
                                 double* f) const {
  for (int k = 0; k < numDofs(); ++k)
    f[k] = 0.0;
  forEachPoint(x, [&](int q, const double* point, const double*, double w) {
    double value[3] = {0.0, 0.0, 0.0};
    t(point, value);
    const double* N = &N_[q * numNodes_];
    for (int a = 0; a < numNodes_; ++a)
      for (int i = 0; i < spaceDim_; ++i)
        f[a * spaceDim_ + i] += w * N[a] * value[i];
  });
}

void SurfaceLoadKernel::pressure(const double* x, double p, double* f) const {
  pressure(
      x, [p](const double*) { return p; }, f);
}

void SurfaceLoadKernel::pressure(const double* x, const std::function<double(const double* x)>& p,
                                 double* f) const {
  for (int k = 0; k < numDofs(); ++k)
    f[k] = 0.0;
  forEachPoint(x, [&](int q, const double* point, const double* normal, double w) {
    const double s = -w * p(point);
    const double* N = &N_[q * numNodes_];
    for (int a = 0; a < numNodes_; ++a)
      for (int i = 0; i < spaceDim_; ++i)
        f[a * spaceDim_ + i] += s * N[a] * normal[i];
  });
}

void SurfaceLoadKernel::followerPressure(const double* x, const double* u, double p, double* f,
                                         double* dfdu) const {
  const int n = numNodes_, D = spaceDim_, refDim = D - 1, nd = numDofs();
  std::fill(f, f + nd, 0.0);
  if (dfdu) std::fill(dfdu, dfdu + nd * nd, 0.0);
  for (int q = 0; q < rule_->size(); ++q) {
    const double* N = &N_[q * n];
    const double* dN = &dNdxi_[q * n * refDim];
    // Current tangents g_j = d(x + u)/dxi_j; in 2D the second is e_z, so that n da / dxi =
    // g_0 x g_1 in both cases.
    double g[2][3] = {{0, 0, 0}, {0, 0, D == 2 ? 1.0 : 0.0}};
    for (int a = 0; a < n; ++a)
      for (int j = 0; j < refDim; ++j)
        for (int i = 0; i < D; ++i)
          g[j][i] += (x[3 * a + i] + u[a * D + i]) * dN[a * refDim + j];
    const double m[3] = {g[0][1] * g[1][2] - g[0][2] * g[1][1],
                         g[0][2] * g[1][0] - g[0][0] * g[1][2],
                         g[0][0] * g[1][1] - g[0][1] * g[1][0]};
    // Axisymmetric: the ring's area element 2 pi r ds at the current radius r = sum N_a (x + u)_a.
    double ring = 1.0;
    if (axisymmetric_) {
      ring = 0.0;
      for (int a = 0; a < n; ++a)
        ring += 2.0 * M_PI * N[a] * (x[3 * a] + u[a * D]);
    }
    const double s = -p * rule_->weights[q];
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < D; ++i)
        f[a * D + i] += s * ring * N[a] * m[i];
    if (!dfdu) continue;
    for (int b = 0; b < n; ++b) {
      // dm/dx_(b k) = dN_b/dxi_0 (e_k x g_1) + dN_b/dxi_1 (g_0 x e_k) = e_k x c (in 2D only
      // the first term: g_1 = e_z does not move), so dm_i/dx_(b k) = eps_ikl c_l = A[i][k].
      const double d0 = dN[b * refDim], d1 = refDim > 1 ? dN[b * refDim + 1] : 0.0;
      double c[3];
      for (int l = 0; l < 3; ++l)
        c[l] = d0 * g[1][l] - d1 * g[0][l];
      const double A[3][3] = {{0, c[2], -c[1]}, {-c[2], 0, c[0]}, {c[1], -c[0], 0}};
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < D; ++i) {
          double* row = dfdu + (a * D + i) * nd + b * D;
          for (int k = 0; k < D; ++k)
            row[k] += s * N[a] * ring * A[i][k];
          // d(2 pi r)/du_(b r) = 2 pi N_b: the ring widens with the radial displacement.
          if (axisymmetric_) row[0] += s * N[a] * 2.0 * M_PI * N[b] * m[i];
        }
    }
  }
}

}  // namespace contactlab
