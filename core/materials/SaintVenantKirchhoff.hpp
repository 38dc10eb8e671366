#pragma once
// Saint Venant-Kirchhoff hyperelasticity, finite strain: the linear-elastic law written between
// the Green-Lagrange strain E = (F^T F - I) / 2 and the second Piola-Kirchhoff stress,
//   S = lambda tr(E) I + 2 mu E,   P = F S,
// with lambda, mu from E and nu as in LinearElastic. It reduces to linear elasticity at small
// strain and is frame invariant, but it softens in compression (in uniaxial stress the
// compressive P_11 = E s (s^2 - 1) / 2 peaks at the stretch s = 1/sqrt(3) and vanishes as s -> 0),
// so it is meant for large rotations with small strains.
// Plane strain is this law with F_zz = 1 and F_xz = F_zx = F_yz = F_zy = 0 (see Material.hpp).
// Temperature: F = F_e F_theta (ThermalExpansion.hpp, evaluateWithThermalStretch).
#include "core/materials/Material.hpp"
#include "core/materials/ThermalExpansion.hpp"

namespace contactlab {

class SaintVenantKirchhoff : public Material {
 public:
  // Throws std::invalid_argument when E <= 0, nu is outside (-1, 0.5) or density < 0.
  SaintVenantKirchhoff(double youngModulus, double poissonRatio, double density = 0.0,
                       const ThermalExpansion& expansion = {});

  std::string name() const override { return "saint-venant-kirchhoff"; }
  Kinematics kinematics() const override { return Kinematics::FiniteStrain; }
  // P and the exact dP/dF:
  //   dP_iJ/dF_kL = delta_ik S_JL + lambda F_iJ F_kL + mu (F_iL F_kJ + (F F^T)_ik delta_JL).
  void evaluate(const MaterialInput& in, MaterialOutput& out) const override;
  double density() const override { return density_; }
  std::optional<double> referenceTemperature() const override {
    return expansion_.referenceTemperature;
  }

  double lambda() const { return lambda_; }
  double mu() const { return mu_; }

 private:
  // The law at F without thermal stretch.
  void evaluateIsothermal(const MaterialInput& in, MaterialOutput& out) const;

  const double E_, nu_, density_;
  const ThermalExpansion expansion_;
  double lambda_ = 0.0, mu_ = 0.0;
};

}  // namespace contactlab
