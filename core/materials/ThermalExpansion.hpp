#pragma once
// Isotropic thermal expansion: the thermal strain is eps_th = alpha(T) (T - T_ref), alpha the
// secant coefficient measured from the stress-free reference temperature T_ref (code_aster's
// ALPHA with TEMP_DEF_ALPHA = T_ref, RCC-M's tables of mean coefficients from 20 C).
//  - A small-strain law takes its elastic strain as eps - eps_th I: in Voigt form only the normal
//    components xx, yy, zz (the hoop strain tt in axisymmetry) lose it.
//  - A finite-strain law takes the multiplicative split F = F_e F_theta, F_theta = theta I with
//    theta = 1 + eps_th (Lu & Pister 1975; Holzapfel, Nonlinear Solid Mechanics, 2000,
//    section 6.5 for the volumetric-thermal split): evaluateWithThermalStretch below.
#include "core/materials/Material.hpp"
#include "core/materials/TemperatureDependent.hpp"

#include <sstream>

namespace contactlab {

struct ThermalExpansion {
  TemperatureDependent coefficient{0.0};  // alpha, 1/K (1/degC)
  double referenceTemperature = 20.0;     // T_ref, degC: no thermal strain at it

  double strain(double temperature) const {
    return coefficient.at(temperature) * (temperature - referenceTemperature);
  }
};

// A finite-strain law with the thermal stretch F_theta = theta I: its energy per unit
// intermediate volume W_e(F_e), F_e = F / theta, is theta^3 W_e per unit reference volume, so
//   P = theta^2 P_e(F / theta),   dP/dF = theta dP_e/dF_e(F / theta),
// and the Cauchy stress P F^T / J is the law's own at F_e (a free expansion F = theta I is
// stress-free). A law with internal variables (F_e F_p) keeps them in the intermediate
// configuration: F_theta, a multiple of I, commutes with F_p. `isothermal(in, out)` is the law at
// in.F; without a temperature it is called on `in` itself (results unchanged bit for bit).
template <class Isothermal>
void evaluateWithThermalStretch(const ThermalExpansion& expansion, const char* law,
                                const MaterialInput& in, MaterialOutput& out,
                                const Isothermal& isothermal) {
  if (!in.temperature) {
    isothermal(in, out);
    return;
  }
  const double theta = 1.0 + expansion.strain(*in.temperature);
  if (!(theta > 0.0)) {
    std::ostringstream s;
    s << law << ": the thermal stretch 1 + alpha (T - T_ref) = " << theta
      << " <= 0 at T = " << *in.temperature;
    out.failed = true;
    out.failure = s.str();
    return;
  }
  MaterialInput elastic = in;
  for (double& f : elastic.F)
    f /= theta;
  isothermal(elastic, out);
  for (double& p : out.P)
    p *= theta * theta;
  for (double& d : out.dPdF)
    d *= theta;
}

}  // namespace contactlab
