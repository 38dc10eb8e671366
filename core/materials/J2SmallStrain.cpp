#include "core/materials/J2SmallStrain.hpp"

#include "core/materials/ParameterCheck.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace contactlab {
namespace {

void require(bool ok, const std::string& what, double got) {
  requireParameter("j2-small-strain", ok, what, got);
}

// Voigt tensor components: the shear rows count twice in a double contraction.
// A table's range check is a check at every temperature (TemperatureDependent::values).
template <class Predicate>
void requireEach(const TemperatureDependent& f, Predicate ok, const std::string& what) {
  for (double v : f.values())
    require(ok(v), what, v);
}

void lameConstants(double E, double nu, double& lambda, double& mu) {
  lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  mu = E / (2.0 * (1.0 + nu));
}

double norm(const double (&t)[6]) {
  return std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2] +
                   2.0 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5]));
}

}  // namespace

J2SmallStrain::J2SmallStrain(const Parameters& parameters) : parameters_(parameters) {
  const Parameters& p = parameters_;
  requireEach(
      p.youngModulus, [](double E) { return E > 0.0; }, "Young's modulus E must be > 0");
  requireEach(
      p.poissonRatio, [](double nu) { return nu > -1.0 && nu < 0.5; },
      "Poisson's ratio nu must lie in (-1, 0.5)");
  requireEach(
      p.yieldStress, [](double s) { return s > 0.0; }, "Yield Stress must be > 0");
  requireEach(
      p.isotropicHardening, [](double H) { return H >= 0.0; },
      "Isotropic Hardening Modulus must be >= 0");
  requireEach(
      p.kinematicHardening, [](double H) { return H >= 0.0; },
      "Kinematic Hardening Modulus must be >= 0");
  require(std::isfinite(p.expansion.referenceTemperature), "Reference Temperature must be finite",
          p.expansion.referenceTemperature);
  require(p.density >= 0.0, "density must be >= 0", p.density);
  const double T = p.expansion.referenceTemperature;
  lameConstants(p.youngModulus.at(T), p.poissonRatio.at(T), lambda_, mu_);
}

void J2SmallStrain::initializeState(double* state) const {
  std::fill(state, state + kStateSize, 0.0);
}

void J2SmallStrain::evaluate(const MaterialInput& in, MaterialOutput& out) const {
  const Parameters& parameters = parameters_;
  const double T = in.temperature.value_or(parameters.expansion.referenceTemperature);
  double lambda = lambda_, mu = mu_;
  if (!parameters.youngModulus.isConstant() || !parameters.poissonRatio.isConstant())
    lameConstants(parameters.youngModulus.at(T), parameters.poissonRatio.at(T), lambda, mu);
  const double Hiso = parameters.isotropicHardening.at(T);
  const double Hkin = parameters.kinematicHardening.at(T);
  // Without a temperature nothing is subtracted: the strain is used bit for bit as before.
  const double thermal = in.temperature ? parameters.expansion.strain(T) : 0.0;
  double state[kStateSize];
  std::copy(in.stateOld, in.stateOld + kStateSize, state);
  double* plasticStrain = state + kPlasticStrain;
  double* backStress = state + kBackStress;
  double& p = state[kEquivalentPlasticStrain];

  // Elastic trial stress and its relative stress xi = dev(sigma_trial) - alpha.
  double eps[6];
  for (int a = 0; a < 6; ++a)
    eps[a] = in.strain[a] - plasticStrain[a] - (a < 3 ? thermal : 0.0);
  const double trace = eps[0] + eps[1] + eps[2];
  for (int a = 0; a < 3; ++a)
    out.stress[a] = lambda * trace + 2.0 * mu * eps[a];
  for (int a = 3; a < 6; ++a)
    out.stress[a] = mu * eps[a];  // engineering shear strain
  const double meanStress = (out.stress[0] + out.stress[1] + out.stress[2]) / 3.0;
  double xi[6];
  for (int a = 0; a < 6; ++a)
    xi[a] = out.stress[a] - (a < 3 ? meanStress : 0.0) - backStress[a];
  const double xiNorm = norm(xi);
  const double qTrial = std::sqrt(1.5) * xiNorm;
  const double yield = parameters.yieldStress.at(T) + Hiso * p;
  const double f = qTrial - yield;

  out.tangent.fill(0.0);
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b)
      out.tangent[a * 6 + b] = lambda;
    out.tangent[a * 6 + a] += 2.0 * mu;
    out.tangent[(a + 3) * 6 + (a + 3)] = mu;
  }
  if (f <= kYieldTolerance * yield) {  // elastic: the trial state is the state
    std::copy(state, state + kStateSize, out.stateNew);
    return;
  }

  // Radial return: f(dp) = f_trial - (3 mu + H_iso + H_kin) dp = 0.
  const double dp = f / (3.0 * mu + Hiso + Hkin);
  double n[6];
  for (int a = 0; a < 6; ++a)
    n[a] = xi[a] / xiNorm;
  for (int a = 0; a < 6; ++a) {
    out.stress[a] -= 2.0 * mu * std::sqrt(1.5) * dp * n[a];
    plasticStrain[a] += (a < 3 ? 1.0 : 2.0) * std::sqrt(1.5) * dp * n[a];
    backStress[a] += std::sqrt(2.0 / 3.0) * Hkin * dp * n[a];
  }
  p += dp;
  std::copy(state, state + kStateSize, out.stateNew);

  // Consistent tangent C - 6 mu^2 / (3 mu + H) n x n - 6 mu^2 dp / q_trial (I_dev - n x n),
  // H = H_iso + H_kin, q_trial = sqrt(3/2) |xi_trial|; in Voigt form with engineering shear
  // strains I_dev has 1/2 on the shear diagonal and n x n takes the tensor components of n.
  const double cN = 6.0 * mu * mu / (3.0 * mu + Hiso + Hkin);
  const double cDev = 6.0 * mu * mu * dp / qTrial;
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b) {
      double iDev = 0.0;
      if (a < 3 && b < 3)
        iDev = (a == b ? 1.0 : 0.0) - 1.0 / 3.0;
      else if (a == b)
        iDev = 0.5;
      out.tangent[a * 6 + b] -= cN * n[a] * n[b] + cDev * (iDev - n[a] * n[b]);
    }
}

}  // namespace contactlab
