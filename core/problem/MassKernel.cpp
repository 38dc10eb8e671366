#include "core/problem/MassKernel.hpp"

#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <cmath>

namespace contactlab {

MassKernel::MassKernel(ElementType type, bool axisymmetric)
    : dim_(info(type).dim), numNodes_(info(type).nodes), axisymmetric_(axisymmetric) {
  rule_ = &quadratureRule(type, 2 * info(type).order);
  const ReferenceElement& ref = ReferenceElement::get(type);
  const int nq = rule_->size();
  N_.resize(static_cast<std::size_t>(nq * numNodes_));
  dNdxi_.resize(static_cast<std::size_t>(nq * numNodes_ * dim_));
  for (int q = 0; q < nq; ++q) {
    ref.shape(&rule_->points[q * dim_], &N_[q * numNodes_]);
    ref.shapeDerivatives(&rule_->points[q * dim_], &dNdxi_[q * numNodes_ * dim_]);
  }
}

void MassKernel::add(const double* x, double density, bool lumped, double* mass) const {
  const int n = numNodes_, nd = numDofs();
  std::vector<double> m(static_cast<std::size_t>(n * n), 0.0), dNdx(dNdxi_.size() / rule_->size());
  for (int q = 0; q < rule_->size(); ++q) {
    double w = density * rule_->weights[q] *
               physicalGradients(dim_, n, x, &dNdxi_[q * n * dim_], dNdx.data());
    const double* N = &N_[q * n];
    if (axisymmetric_) {
      double r = 0.0;
      for (int a = 0; a < n; ++a)
        r += N[a] * x[3 * a];
      w *= 2.0 * M_PI * r;
    }
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        m[a * n + b] += w * N[a] * N[b];
  }
  if (lumped) {
    double total = 0.0, diagonal = 0.0;
    for (int a = 0; a < n; ++a) {
      diagonal += m[a * n + a];
      for (int b = 0; b < n; ++b)
        total += m[a * n + b];
    }
    for (int a = 0; a < n; ++a) {
      const double ma = diagonal > 0 ? m[a * n + a] * total / diagonal : 0.0;
      for (int b = 0; b < n; ++b)
        m[a * n + b] = a == b ? ma : 0.0;
    }
  }
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int i = 0; i < dim_; ++i)
        mass[(a * dim_ + i) * nd + b * dim_ + i] += m[a * n + b];
}

}  // namespace contactlab
