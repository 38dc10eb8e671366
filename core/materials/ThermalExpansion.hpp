#pragma once
// Isotropic thermal expansion of a small-strain law: the thermal strain is
// eps_th = alpha(T) (T - T_ref) I, alpha the secant coefficient measured from the stress-free
// reference temperature T_ref (code_aster's ALPHA with TEMP_DEF_ALPHA = T_ref, RCC-M's tables
// of mean coefficients from 20 C). The law takes its elastic strain as eps - eps_th: in Voigt
// form only the normal components xx, yy, zz (the hoop strain tt in axisymmetry) lose it.
#include "core/materials/TemperatureDependent.hpp"

namespace contactlab {

struct ThermalExpansion {
  TemperatureDependent coefficient{0.0};  // alpha, 1/K (1/degC)
  double referenceTemperature = 20.0;     // T_ref, degC: no thermal strain at it

  double strain(double temperature) const {
    return coefficient.at(temperature) * (temperature - referenceTemperature);
  }
};

}  // namespace contactlab
