#include "core/materials/LinearElastic.hpp"

#include "core/materials/ParameterCheck.hpp"

#include <stdexcept>

namespace contactlab {

LinearElastic::LinearElastic(double youngModulus, double poissonRatio, double density)
    : E_(youngModulus), nu_(poissonRatio), density_(density) {
  requireParameter("linear-elastic", E_ > 0.0, "Young's modulus E must be > 0", E_);
  requireParameter("linear-elastic", nu_ > -1.0 && nu_ < 0.5,
                   "Poisson's ratio nu must lie in (-1, 0.5)", nu_);
  if (!(density_ >= 0.0)) throw std::invalid_argument("linear-elastic: density must be >= 0");
  const double lambda = E_ * nu_ / ((1.0 + nu_) * (1.0 - 2.0 * nu_));
  const double mu = E_ / (2.0 * (1.0 + nu_));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      C_[i * 6 + j] = lambda;
    C_[i * 6 + i] += 2.0 * mu;
    C_[(i + 3) * 6 + (i + 3)] = mu;  // engineering shears
  }
}

void LinearElastic::evaluate(const MaterialInput& in, MaterialOutput& out) const {
  for (int i = 0; i < 6; ++i) {
    double s = 0.0;
    for (int j = 0; j < 6; ++j)
      s += C_[i * 6 + j] * in.strain[j];
    out.stress[i] = s;
  }
  out.tangent = C_;
}

}  // namespace contactlab
