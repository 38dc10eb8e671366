#include "core/materials/LinearElastic.hpp"

#include "core/materials/ParameterCheck.hpp"

#include <cmath>
#include <stdexcept>

namespace contactlab {
namespace {

LinearElastic::Parameters constantParameters(double E, double nu, double density) {
  LinearElastic::Parameters p;
  p.youngModulus = E;
  p.poissonRatio = nu;
  p.density = density;
  return p;
}

std::array<double, 36> isotropicStiffness(double E, double nu) {
  const double lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double mu = E / (2.0 * (1.0 + nu));
  std::array<double, 36> C{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      C[i * 6 + j] = lambda;
    C[i * 6 + i] += 2.0 * mu;
    C[(i + 3) * 6 + (i + 3)] = mu;  // engineering shears
  }
  return C;
}

}  // namespace

LinearElastic::LinearElastic(double youngModulus, double poissonRatio, double density)
    : LinearElastic(constantParameters(youngModulus, poissonRatio, density)) {}

LinearElastic::LinearElastic(const Parameters& parameters) : parameters_(parameters) {
  for (double E : parameters_.youngModulus.values())
    requireParameter("linear-elastic", E > 0.0, "Young's modulus E must be > 0", E);
  for (double nu : parameters_.poissonRatio.values())
    requireParameter("linear-elastic", nu > -1.0 && nu < 0.5,
                     "Poisson's ratio nu must lie in (-1, 0.5)", nu);
  requireParameter("linear-elastic", std::isfinite(parameters_.expansion.referenceTemperature),
                   "Reference Temperature must be finite",
                   parameters_.expansion.referenceTemperature);
  if (!(parameters_.density >= 0.0))
    throw std::invalid_argument("linear-elastic: density must be >= 0");
  if (parameters_.youngModulus.isConstant() && parameters_.poissonRatio.isConstant())
    C_ = isotropicStiffness(parameters_.youngModulus.at(0.0), parameters_.poissonRatio.at(0.0));
}

void LinearElastic::evaluate(const MaterialInput& in, MaterialOutput& out) const {
  const double T = temperature(in.temperature);
  std::array<double, 36> tabulated;
  const bool constant =
      parameters_.youngModulus.isConstant() && parameters_.poissonRatio.isConstant();
  if (!constant)
    tabulated = isotropicStiffness(parameters_.youngModulus.at(T), parameters_.poissonRatio.at(T));
  const std::array<double, 36>& C = constant ? C_ : tabulated;
  std::array<double, 6> elastic = in.strain;
  // Without a temperature there is nothing to subtract: the strain is used as given, bit for
  // bit (a model without temperatures gives the results it gave before they existed).
  if (in.temperature) {
    const double thermal = parameters_.expansion.strain(T);
    for (int i = 0; i < 3; ++i)
      elastic[i] -= thermal;
  }
  for (int i = 0; i < 6; ++i) {
    double s = 0.0;
    for (int j = 0; j < 6; ++j)
      s += C[i * 6 + j] * elastic[j];
    out.stress[i] = s;
  }
  out.tangent = C;
}

}  // namespace contactlab
