#include "core/materials/NeoHookean.hpp"

#include "core/materials/ParameterCheck.hpp"
#include "core/materials/Tensor3.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace contactlab {
namespace {

void require(bool ok, const std::string& what, double got) {
  requireParameter("neo-hookean", ok, what, got);
}

}  // namespace

NeoHookean::Volumetric NeoHookean::volumetricFromName(const std::string& name) {
  if (name == "quadratic") return Volumetric::Quadratic;
  if (name == "simo-miehe") return Volumetric::SimoMiehe;
  throw std::invalid_argument(
      "neo-hookean: Volumetric Energy must be 'quadratic' or "
      "'simo-miehe' (got '" +
      name + "')");
}

NeoHookean::NeoHookean(double C10, double D1, double density, Volumetric volumetric,
                       const ThermalExpansion& expansion)
    : C10_(C10), D1_(D1), density_(density), volumetric_(volumetric), expansion_(expansion) {
  require(C10_ > 0.0, "C10 must be > 0", C10_);
  require(D1_ > 0.0, "D1 must be > 0", D1_);
  require(density_ >= 0.0, "density must be >= 0", density_);
  mu_ = 2.0 * C10_;
  K_ = 2.0 / D1_;
}

NeoHookean NeoHookean::fromYoungPoisson(double E, double nu, double density,
                                        Volumetric volumetric) {
  require(E > 0.0, "Young's modulus E must be > 0", E);
  require(nu > -1.0 && nu < 0.5, "Poisson's ratio nu must lie in (-1, 0.5)", nu);
  const double mu = E / (2.0 * (1.0 + nu));
  const double K = E / (3.0 * (1.0 - 2.0 * nu));
  return NeoHookean(mu / 2.0, 2.0 / K, density, volumetric);
}

NeoHookean NeoHookean::fromParameters(double E, double nu, double C10, double D1, double density,
                                      Volumetric volumetric) {
  const bool youngPoisson = E != 0.0;
  const bool coefficients = C10 != 0.0 || D1 != 0.0;
  if (youngPoisson && coefficients) {
    std::ostringstream s;
    s << "neo-hookean: give either E and nu or C10 and D1, not both (got E = " << E
      << ", C10 = " << C10 << ", D1 = " << D1 << ")";
    throw std::invalid_argument(s.str());
  }
  if (youngPoisson) return fromYoungPoisson(E, nu, density, volumetric);
  if (!coefficients)
    throw std::invalid_argument(
        "neo-hookean: give either E and nu or C10 and D1 (E, C10 and D1 are all 0, which reads "
        "as not given)");
  require(nu == kDefaultPoissonRatio,
          "nu is used only with E; leave it out when C10 and D1 are given", nu);
  return NeoHookean(C10, D1, density, volumetric);
}

void NeoHookean::evaluate(const MaterialInput& in, MaterialOutput& out) const {
  evaluateWithThermalStretch(
      expansion_, "neo-hookean", in, out,
      [this](const MaterialInput& i, MaterialOutput& o) { evaluateIsothermal(i, o); });
}

void NeoHookean::evaluateIsothermal(const MaterialInput& in, MaterialOutput& out) const {
  using namespace tensor3;
  const Mat3& F = in.F;
  const double detF = determinant(F);  // J
  if (!(detF > 0.0)) {                 // also catches a NaN J
    out.P.fill(0.0);
    out.dPdF.fill(0.0);
    out.failed = true;
    std::ostringstream s;
    s << "neo-hookean: J = " << detF << " <= 0";
    out.failure = s.str();
    return;
  }
  const Mat3 Finv = inverse(F, detF);  // (F^-T)_iJ = Finv[J * 3 + i]
  const double I1 = contract(F, F);
  const double a = std::pow(detF, -2.0 / 3.0);
  // v = J U'(J) and J dv/dJ: quadratic K J (J - 1), K J (2 J - 1); simo-miehe K (J^2 - 1) / 2,
  // K J^2.
  const bool quadratic = volumetric_ == Volumetric::Quadratic;
  const double volumetric = quadratic ? K_ * detF * (detF - 1.0) : 0.5 * K_ * (detF * detF - 1.0);
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J)
      out.P[i * 3 + J] =
          mu_ * a * (F[i * 3 + J] - I1 / 3.0 * Finv[J * 3 + i]) + volumetric * Finv[J * 3 + i];

  // Derivatives: d(J^-2/3)/dF_kL = -2/3 J^-2/3 Finv_Lk, dJ/dF_kL = J Finv_Lk,
  // d(F^-T)_iJ/dF_kL = -Finv_Jk Finv_Li, dI1/dF_kL = 2 F_kL.
  const double dVolumetric = quadratic ? K_ * (2.0 * detF - 1.0) * detF : K_ * detF * detF;
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J) {
      const double devPart = F[i * 3 + J] - I1 / 3.0 * Finv[J * 3 + i];
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L) {
          double iso = -2.0 / 3.0 * Finv[L * 3 + k] * devPart -
                       2.0 / 3.0 * F[k * 3 + L] * Finv[J * 3 + i] +
                       I1 / 3.0 * Finv[J * 3 + k] * Finv[L * 3 + i];
          if (i == k && J == L) iso += 1.0;
          out.dPdF[(i * 3 + J) * 9 + k * 3 + L] = mu_ * a * iso +
                                                  dVolumetric * Finv[L * 3 + k] * Finv[J * 3 + i] -
                                                  volumetric * Finv[J * 3 + k] * Finv[L * 3 + i];
        }
    }
}

}  // namespace contactlab
