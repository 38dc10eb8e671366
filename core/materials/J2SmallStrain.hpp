#pragma once
// Von Mises (J2) plasticity, small strain, with linear isotropic and linear kinematic (Prager)
// hardening, integrated by backward Euler (radial return, closed form for linear hardening)
// with the consistent (algorithmic) tangent.
//
//   sigma = C : (eps - eps_p)                 (C isotropic: lambda, mu from E, nu)
//   xi = dev(sigma) - alpha,  n = xi / |xi|
//   f = sqrt(3/2) |xi| - (sigma_y0 + H_iso p) <= 0
//   d eps_p = dp sqrt(3/2) n,  d alpha = (2/3) H_kin d eps_p,  d p = dp >= 0
//
// p is the equivalent plastic strain (sqrt(2/3) |d eps_p| per step). In uniaxial stress the
// plastic modulus is H = H_iso + H_kin: sigma = sigma_y0 + E H / (E + H) (eps - sigma_y0 / E)
// after first yield; with H_iso = 0 a reversal yields at sigma_max - 2 sigma_y0 (Bauschinger).
// Plane strain is this law with eps_zz = eps_yz = eps_xz = 0 (see Material.hpp).
//
// Temperature (Material.hpp): eps is replaced by eps - alpha (T - T_ref) I
// (ThermalExpansion.hpp), and E, nu, sigma_y0, H_iso, H_kin may be tabulated in T. Each step
// is isothermal: the moduli, yield stress and hardening are those at the step's temperature,
// applied to the whole state (sigma = C(T) : (eps - eps_p - eps_th(T)), the yield surface
// sigma_y0(T) + H_iso(T) p), without the temperature-rate terms of a thermoplastic law (Simo &
// Miehe 1992): exact for a constant T, and the usual approximation when T changes slowly.
//
// State per quadrature point (kStateSize = 13 doubles):
//   [0, 6)   plastic strain eps_p, Voigt xx yy zz xy yz xz, engineering shears (like the strain)
//   [6, 12)  back stress alpha, Voigt xx yy zz xy yz xz, stress components (deviatoric)
//   [12]     equivalent plastic strain p
#include "core/materials/Material.hpp"
#include "core/materials/TemperatureDependent.hpp"
#include "core/materials/ThermalExpansion.hpp"

namespace contactlab {

class J2SmallStrain : public Material {
 public:
  static constexpr int kPlasticStrain = 0;
  static constexpr int kBackStress = 6;
  static constexpr int kEquivalentPlasticStrain = 12;
  static constexpr int kStateSize = 13;
  // A trial state yields when f > kYieldTolerance (sigma_y0 + H_iso p): a point left exactly on
  // the yield surface by the previous step and loaded by round-off only stays elastic.
  static constexpr double kYieldTolerance = 1e-12;

  struct Parameters {
    // Each a constant or a table in T; the ranges hold at every temperature.
    TemperatureDependent youngModulus{1.0};        // E > 0
    TemperatureDependent poissonRatio{0.3};        // nu in (-1, 0.5)
    TemperatureDependent yieldStress{0.0};         // sigma_y0 > 0
    TemperatureDependent isotropicHardening{0.0};  // H_iso >= 0
    TemperatureDependent kinematicHardening{0.0};  // H_kin >= 0
    ThermalExpansion expansion;                    // alpha = 0 by default: no thermal strain
    double density = 0.0;                          // >= 0
  };

  // Throws std::invalid_argument naming the parameter when a value is outside its range.
  explicit J2SmallStrain(const Parameters& parameters);

  std::string name() const override { return "j2-small-strain"; }
  Kinematics kinematics() const override { return Kinematics::SmallStrain; }
  int stateSize() const override { return kStateSize; }
  // Zero plastic strain, back stress and equivalent plastic strain.
  void initializeState(double* state) const override;
  // Reads in.stateOld and writes the whole trial state to out.stateNew (a copy of stateOld in
  // an elastic step); both are required. out.stateNew may alias in.stateOld.
  void evaluate(const MaterialInput& in, MaterialOutput& out) const override;
  double density() const override { return parameters_.density; }
  bool isochoricFlow() const override { return true; }
  double equivalentPlasticStrain(const double* state) const override {
    return state[kEquivalentPlasticStrain];
  }
  std::optional<double> referenceTemperature() const override {
    return parameters_.expansion.referenceTemperature;
  }

  const Parameters& parameters() const { return parameters_; }
  // Lame's constants at the reference temperature.
  double lambda() const { return lambda_; }
  double mu() const { return mu_; }

 private:
  const Parameters parameters_;
  double lambda_ = 0.0, mu_ = 0.0;  // at the reference temperature (every T when E, nu constant)
};

}  // namespace contactlab
