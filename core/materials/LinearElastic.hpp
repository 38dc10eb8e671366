#pragma once
// Isotropic linear elasticity, small strain: sigma = lambda tr(eps_e) I + 2 mu eps_e, with the
// elastic strain eps_e = eps - alpha (T - T_ref) I (ThermalExpansion.hpp) and E, nu, alpha
// optionally tabulated in the temperature T. Plane strain is this law with the out-of-plane
// strains zero (see Material.hpp): a heated plane-strain slice then carries sigma_zz.
#include "core/materials/Material.hpp"
#include "core/materials/TemperatureDependent.hpp"
#include "core/materials/ThermalExpansion.hpp"

namespace contactlab {

class LinearElastic : public Material {
 public:
  struct Parameters {
    TemperatureDependent youngModulus{1.0};  // E > 0 at every temperature
    TemperatureDependent poissonRatio{0.3};  // nu in (-1, 0.5) at every temperature
    ThermalExpansion expansion;              // alpha = 0 by default: no thermal strain
    double density = 0.0;                    // >= 0
  };

  // Throws std::invalid_argument when E <= 0 or nu is outside (-1, 0.5) (at some tabulated
  // temperature), or the density is negative.
  explicit LinearElastic(const Parameters& parameters);
  LinearElastic(double youngModulus, double poissonRatio, double density = 0.0);

  std::string name() const override { return "linear-elastic"; }
  Kinematics kinematics() const override { return Kinematics::SmallStrain; }
  void evaluate(const MaterialInput& in, MaterialOutput& out) const override;
  double density() const override { return parameters_.density; }
  bool linear() const override { return true; }
  std::optional<double> referenceTemperature() const override {
    return parameters_.expansion.referenceTemperature;
  }

  // At the reference temperature.
  double youngModulus() const { return parameters_.youngModulus.at(temperature({})); }
  double poissonRatio() const { return parameters_.poissonRatio.at(temperature({})); }
  const Parameters& parameters() const { return parameters_; }

 private:
  double temperature(const std::optional<double>& given) const {
    return given.value_or(parameters_.expansion.referenceTemperature);
  }
  const Parameters parameters_;
  std::array<double, 36> C_{};  // the stiffness when E and nu are constant
};

}  // namespace contactlab
