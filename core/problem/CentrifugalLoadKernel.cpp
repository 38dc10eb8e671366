#include "core/problem/CentrifugalLoadKernel.hpp"

#include <cmath>
#include <stdexcept>

namespace contactlab {

CentrifugalLoadKernel::CentrifugalLoadKernel(const CentrifugalLoad& load, int dim,
                                             bool axisymmetric)
    : load_(load), dim_(dim) {
  const auto& a = load.axis;
  const double norm = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  if (!(norm > 0) || !std::isfinite(norm))
    throw std::invalid_argument("centrifugal load '" + load.name + "': the axis is zero");
  if (axisymmetric && (a[0] != 0 || a[2] != 0 || load.centre[0] != 0))
    throw std::invalid_argument("centrifugal load '" + load.name +
                                "': an axisymmetric model spins about its own axis, the y axis "
                                "(x = 0): give a Centre with x = 0");
  if (dim == 2 && !axisymmetric && (a[0] != 0 || a[1] != 0))
    throw std::invalid_argument("centrifugal load '" + load.name +
                                "': a 2D model spins about the z axis only");
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      projector_[3 * i + j] = (i == j ? 1.0 : 0.0) - a[i] * a[j] / (norm * norm);
}

double CentrifugalLoadKernel::intensity(double t) const {
  return load_.density * load_.angularVelocity * load_.angularVelocity * load_.function(t);
}

void CentrifugalLoadKernel::addForce(const double* mass, const double* x, int numNodes, double t,
                                     double* f) const {
  const double c = intensity(t);
  const int nd = numNodes * dim_;
  for (int a = 0; a < numNodes; ++a)
    for (int b = 0; b < numNodes; ++b) {
      const double m = c * mass[(a * dim_) * nd + b * dim_];  // M_ab (the x-x entry)
      for (int i = 0; i < dim_; ++i) {
        double r = 0;
        for (int j = 0; j < dim_; ++j)
          r += projector_[3 * i + j] * (x[3 * b + j] - load_.centre[j]);
        f[a * dim_ + i] += m * r;
      }
    }
}

void CentrifugalLoadKernel::addStiffness(const double* mass, int numNodes, double t,
                                         double* k) const {
  const double c = intensity(t);
  const int nd = numNodes * dim_;
  for (int a = 0; a < numNodes; ++a)
    for (int b = 0; b < numNodes; ++b) {
      const double m = c * mass[(a * dim_) * nd + b * dim_];
      for (int i = 0; i < dim_; ++i)
        for (int j = 0; j < dim_; ++j)
          k[(a * dim_ + i) * nd + b * dim_ + j] -= m * projector_[3 * i + j];
    }
}

}  // namespace contactlab
