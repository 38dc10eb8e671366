#pragma once
// Compressible neo-Hookean hyperelasticity, finite strain:
//   W = C10 (I1bar - 3) + U(J),   J = det F,   I1bar = J^(-2/3) tr(F^T F),
// with the shear modulus mu = 2 C10 and the bulk modulus K = 2 / D1, and one of two volumetric
// energies (both U''(1) = K, so they agree at small strain and differ at finite J):
//   quadratic:   U = (1 / D1) (J - 1)^2 = K/2 (J - 1)^2   (Abaqus, code_aster), the default;
//   simo-miehe:  U = K/4 (J^2 - 1 - 2 ln J)              (Simo & Miehe 1991; deal.II's
//                                                        finite-strain examples).
//   P = mu J^(-2/3) (F - (tr(F^T F) / 3) F^-T) + J U'(J) F^-T.
// At small strain it is linear elasticity with lambda = K - 2 mu / 3 and mu.
// Plane strain is this law with F_zz = 1 and F_xz = F_zx = F_yz = F_zy = 0 (see Material.hpp).
// J <= 0 (an inverted or degenerate point) is not evaluated: `evaluate` sets `failed`.
// Temperature: F = F_e F_theta (ThermalExpansion.hpp, evaluateWithThermalStretch).
#include "core/materials/Material.hpp"
#include "core/materials/ThermalExpansion.hpp"

namespace contactlab {

class NeoHookean : public Material {
 public:
  enum class Volumetric { Quadratic, SimoMiehe };
  // "quadratic" or "simo-miehe"; throws std::invalid_argument naming the key otherwise.
  static Volumetric volumetricFromName(const std::string& name);

  // Throws std::invalid_argument when C10 <= 0, D1 <= 0 or density < 0.
  NeoHookean(double C10, double D1, double density = 0.0,
             Volumetric volumetric = Volumetric::Quadratic, const ThermalExpansion& expansion = {});
  // The same law with a thermal expansion.
  NeoHookean withThermalExpansion(const ThermalExpansion& expansion) const {
    return NeoHookean(C10_, D1_, density_, volumetric_, expansion);
  }
  // From Young's modulus and Poisson's ratio: mu = E / (2 (1 + nu)), K = E / (3 (1 - 2 nu)),
  // C10 = mu / 2, D1 = 2 / K. Throws when E <= 0 or nu is outside (-1, 0.5).
  static NeoHookean fromYoungPoisson(double E, double nu, double density = 0.0,
                                     Volumetric volumetric = Volumetric::Quadratic);

  // The registry's parameters: one pair is given, either (E, nu) or (C10, D1). E, C10 and D1
  // default to 0, which reads as "not given" (0 is not a valid value of any of them); nu
  // defaults to kDefaultPoissonRatio and is used only with E. Throws std::invalid_argument,
  // naming the keys, when both pairs or neither are given, when nu differs from its default
  // while C10 / D1 are given, and for the invalid values of the constructors above.
  static constexpr double kDefaultPoissonRatio = 0.3;
  static NeoHookean fromParameters(double E, double nu, double C10, double D1, double density,
                                   Volumetric volumetric = Volumetric::Quadratic);

  std::string name() const override { return "neo-hookean"; }
  Kinematics kinematics() const override { return Kinematics::FiniteStrain; }
  // P and the exact dP/dF; at J <= 0 sets out.failed and out.failure ("neo-hookean: J = -0.1
  // <= 0"), zeroes P and dP/dF and returns.
  void evaluate(const MaterialInput& in, MaterialOutput& out) const override;
  double density() const override { return density_; }
  std::optional<double> referenceTemperature() const override {
    return expansion_.referenceTemperature;
  }

  double C10() const { return C10_; }
  double D1() const { return D1_; }
  double shearModulus() const { return mu_; }
  double bulkModulus() const { return K_; }

 private:
  // The law at F without thermal stretch.
  void evaluateIsothermal(const MaterialInput& in, MaterialOutput& out) const;

  const double C10_, D1_, density_;
  const Volumetric volumetric_;
  const ThermalExpansion expansion_;
  double mu_ = 0.0, K_ = 0.0;
};

}  // namespace contactlab
