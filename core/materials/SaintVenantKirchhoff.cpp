#include "core/materials/SaintVenantKirchhoff.hpp"

#include "core/materials/ParameterCheck.hpp"
#include "core/materials/Tensor3.hpp"

#include <stdexcept>
#include <string>

namespace contactlab {
namespace {

void require(bool ok, const std::string& what, double got) {
  requireParameter("saint-venant-kirchhoff", ok, what, got);
}

}  // namespace

SaintVenantKirchhoff::SaintVenantKirchhoff(double youngModulus, double poissonRatio, double density,
                                           const ThermalExpansion& expansion)
    : E_(youngModulus), nu_(poissonRatio), density_(density), expansion_(expansion) {
  require(E_ > 0.0, "Young's modulus E must be > 0", E_);
  require(nu_ > -1.0 && nu_ < 0.5, "Poisson's ratio nu must lie in (-1, 0.5)", nu_);
  require(density_ >= 0.0, "density must be >= 0", density_);
  lambda_ = E_ * nu_ / ((1.0 + nu_) * (1.0 - 2.0 * nu_));
  mu_ = E_ / (2.0 * (1.0 + nu_));
}

void SaintVenantKirchhoff::evaluate(const MaterialInput& in, MaterialOutput& out) const {
  evaluateWithThermalStretch(
      expansion_, "saint-venant-kirchhoff", in, out,
      [this](const MaterialInput& i, MaterialOutput& o) { evaluateIsothermal(i, o); });
}

void SaintVenantKirchhoff::evaluateIsothermal(const MaterialInput& in, MaterialOutput& out) const {
  using namespace tensor3;
  const Mat3& F = in.F;
  const Mat3 C = transposeMultiply(F, F);
  Mat3 E = C;  // Green-Lagrange strain
  for (int I = 0; I < 3; ++I)
    E[I * 3 + I] -= 1.0;
  for (double& e : E)
    e *= 0.5;
  Mat3 S = E;
  for (double& s : S)
    s *= 2.0 * mu_;
  const double lambdaTrE = lambda_ * trace(E);
  for (int I = 0; I < 3; ++I)
    S[I * 3 + I] += lambdaTrE;
  out.P = multiply(F, S);

  const Mat3 b = multiplyTranspose(F, F);
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J)
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L) {
          double d = lambda_ * F[i * 3 + J] * F[k * 3 + L] + mu_ * F[i * 3 + L] * F[k * 3 + J];
          if (i == k) d += S[J * 3 + L];
          if (J == L) d += mu_ * b[i * 3 + k];
          out.dPdF[(i * 3 + J) * 9 + k * 3 + L] = d;
        }
}

}  // namespace contactlab
