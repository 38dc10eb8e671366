#pragma once
// Von Mises (J2) elastoplasticity at finite strain: multiplicative split F = Fe Fp, Hencky
// (logarithmic) elasticity and the exponential-map return (Simo 1992; de Souza Neto, Peric &
// Owen, "Computational Methods for Plasticity", 2008, ch. 14), isotropic hardening.
//
//   b_e trial = F C_p^-1_n F^T,   eps_e trial = (1/2) ln b_e trial   (principal frame of b_e)
//   tau = K tr(eps_e) I + 2 G dev(eps_e)                               (Kirchhoff stress)
//   f = sqrt(3/2) |dev tau| - sigma_y(alpha) <= 0
//   radial return on dev tau in the principal frame, exactly as the small-strain law:
//   q trial - 3 G dgamma - sigma_y(alpha_n + dgamma) = 0,
//   eps_e = eps_e trial - dgamma sqrt(3/2) N,   N = dev tau trial / |dev tau trial|
//   b_e = exp(2 eps_e),   C_p^-1 = F^-1 b_e F^-T,   alpha = alpha_n + dgamma,   P = tau F^-T
// K = E / (3 (1 - 2 nu)), G = E / (2 (1 + nu)). The plastic flow is isochoric: det C_p^-1
// stays 1. In coaxial monotone loading (principal axes fixed) the logarithmic strains add,
// ln V = eps_e + eps_p, and the law is the small-strain J2 law between the logarithmic strain
// and the Kirchhoff stress: in uniaxial stress tau = sigma_y0 + H alpha with
// ln(stretch) = tau / E + alpha after first yield.
//
// Hardening, one of two forms (internally the same: knots (alpha_i, sigma_i) with a slope per
// segment):
//  - linear: sigma_y = sigma_y0 + H alpha (H = 0: perfectly plastic);
//  - a tabulated curve (alpha_i, sigma_i), piecewise linear, first point (0, sigma_y0); beyond
//    the last point the curve goes on with the slope of its last segment (so a curve that ends
//    flat is perfectly plastic beyond its end, and one that ends rising keeps hardening; the
//    yield stress is never extrapolated to a constant that would hide the last slope).
//  On either form the return is solved exactly: the yield function is linear on each segment,
//  so the segment holding the root is found by walking from alpha_n (what Newton's method
//  would converge to in one step per segment), with no iteration tolerance to miss.
//
// The tangent is the consistent dP/dF in closed form: the small-strain algorithmic modulus
// d tau / d eps_e trial, times the derivative of the tensor logarithm in the principal frame
// (Daleckii-Krein: the divided differences (ln b_a - ln b_b) / (b_a - b_b), evaluated by a
// series when b_a and b_b are close and equal to 1 / b_a when they coincide, so equal and
// near-equal principal stretches need no special case and nothing blows up), times
// d b_e trial / dF, plus the geometric term of F^-T.
//
// Plane strain is this law with F_zz = 1 and F_xz = F_zx = F_yz = F_zy = 0 (see Material.hpp).
// J <= 0, a non-finite F or a non-finite result set `failed` instead of throwing.
//
// State per quadrature point (kStateSize = 7 doubles):
//   [0, 6)  C_p^-1, the inverse plastic right Cauchy-Green tensor, Voigt xx yy zz xy yz xz
//           (tensor components); I in the virgin state
//   [6]     equivalent plastic strain alpha (sum of dgamma)
#include "core/materials/Material.hpp"
#include "core/materials/ThermalExpansion.hpp"

#include <vector>

namespace contactlab {

class SimoMiehe : public Material {
 public:
  static constexpr int kInversePlasticStrain = 0;  // C_p^-1, 6 components
  static constexpr int kEquivalentPlasticStrain = 6;
  static constexpr int kStateSize = 7;
  // A trial state yields when f > kYieldTolerance sigma_y(alpha_n), as in J2SmallStrain.
  static constexpr double kYieldTolerance = 1e-12;

  struct Parameters {
    double youngModulus = 1.0;        // E > 0
    double poissonRatio = 0.3;        // nu in (0, 0.5)
    double yieldStress = 0.0;         // sigma_y0 > 0
    double isotropicHardening = 0.0;  // H >= 0 (linear form); 0 when a curve is given
    // Tabulated form (both empty: linear). At least two points; strains start at 0 and
    // increase strictly, stresses start at sigma_y0 and do not decrease.
    std::vector<double> hardeningStrains;
    std::vector<double> hardeningStresses;
    double density = 0.0;  // >= 0
    // F = F_e F_theta F_p (ThermalExpansion.hpp); alpha = 0 by default: no thermal stretch.
    ThermalExpansion expansion;
  };

  // Throws std::invalid_argument, "simo-miehe: <rule> (got <value>)" naming the parameter, when
  // a value breaks a rule above or when both a curve and a nonzero linear modulus are given.
  explicit SimoMiehe(const Parameters& parameters);

  std::string name() const override { return "simo-miehe"; }
  Kinematics kinematics() const override { return Kinematics::FiniteStrain; }
  int stateSize() const override { return kStateSize; }
  // C_p^-1 = I, alpha = 0.
  void initializeState(double* state) const override;
  // P, the consistent dP/dF and the trial state. in.stateOld and out.stateNew are required
  // and may alias. At J <= 0 (or a non-finite F or result) sets out.failed and a one-line
  // out.failure ("simo-miehe: J = -0.1 <= 0"), zeroes P and dP/dF, copies stateOld.
  void evaluate(const MaterialInput& in, MaterialOutput& out) const override;
  double density() const override { return parameters_.density; }
  std::optional<double> referenceTemperature() const override {
    return parameters_.expansion.referenceTemperature;
  }
  bool isochoricFlow() const override { return true; }
  double equivalentPlasticStrain(const double* state) const override {
    return state[kEquivalentPlasticStrain];
  }

  const Parameters& parameters() const { return parameters_; }
  double bulkModulus() const { return K_; }
  double shearModulus() const { return G_; }
  // The yield stress sigma_y(alpha) (alpha >= 0) and its slope there (the slope of the segment
  // alpha lies on; at a knot the segment that starts there).
  double yieldStress(double alpha) const;
  double hardeningSlope(double alpha) const;

 private:
  // The law at F without thermal stretch.
  void evaluateIsothermal(const MaterialInput& in, MaterialOutput& out) const;
  // Index of the segment holding alpha: the last knot <= alpha.
  int segment(double alpha) const;

  const Parameters parameters_;
  double K_ = 0.0, G_ = 0.0;
  // Knots alpha_i, sigma_i and the slope of segment i (from knot i to knot i + 1; the last one
  // extends to infinity).
  std::vector<double> knotStrains_, knotStresses_, slopes_;
};

}  // namespace contactlab
