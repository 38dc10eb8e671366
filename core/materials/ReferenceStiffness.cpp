#include "core/materials/ReferenceStiffness.hpp"

#include "base/NumberText.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace contactlab {

namespace {

struct Lame {
  double lambda;
  double mu;
};

Lame restLame(const Material& material) {
  MaterialInput in;
  in.F = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  std::vector<double> stateOld(static_cast<std::size_t>(material.stateSize())),
      stateNew(stateOld.size());
  if (!stateOld.empty()) material.initializeState(stateOld.data());
  in.stateOld = stateOld.empty() ? nullptr : stateOld.data();
  MaterialOutput out;
  out.stateNew = stateNew.empty() ? nullptr : stateNew.data();
  material.evaluate(in, out);
  if (out.failed)
    throw std::invalid_argument(material.name() + " cannot be evaluated at rest: " + out.failure);
  // C_xxxx = lambda + 2 mu, C_xxyy = lambda: small strain in Voigt order (xx, yy, ...), finite
  // strain as dP_xx/dF_xx and dP_xx/dF_yy (dPdF at F = I is the small-strain tangent).
  double c11 = 0, c12 = 0;
  if (material.kinematics() == Kinematics::SmallStrain) {
    c11 = out.tangent[0];
    c12 = out.tangent[1];
  } else {
    c11 = out.dPdF[0];
    c12 = out.dPdF[4];
  }
  const double mu = 0.5 * (c11 - c12), lambda = c12;
  if (!(mu > 0) || !(lambda + 2.0 * mu / 3.0 > 0) || !std::isfinite(c11 + c12))
    throw std::invalid_argument(
        material.name() + " has no stable isotropic stiffness at rest (mu = " + numberText(mu) +
        ", lambda = " + numberText(lambda) + ")");
  return {lambda, mu};
}

}  // namespace

double referenceYoungModulus(const Material& material) {
  const auto [lambda, mu] = restLame(material);
  return mu * (3.0 * lambda + 2.0 * mu) / (lambda + mu);
}

double referencePoissonRatio(const Material& material) {
  const auto [lambda, mu] = restLame(material);
  return lambda / (2.0 * (lambda + mu));
}

}  // namespace contactlab
