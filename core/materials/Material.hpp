#pragma once
// Constitutive law at one quadrature point.
//
// Conventions (fixed for the whole project):
//  - Voigt order xx, yy, zz, xy, yz, xz; strains use engineering shears (gamma = 2 eps).
//  - Plane strain is the 3D law with eps_zz = eps_yz = eps_xz = 0 (finite strain: F_zz = 1,
//    F_xz = F_zx = F_yz = F_zy = 0); the 2D kernels pick the in-plane components and still
//    report sigma_zz. Plane stress is the law wrapped in PlaneStress.hpp, which takes that same
//    input and solves for the eps_zz (F_zz) that makes sigma_zz vanish.
//  - Small-strain laws take the linearized strain and return the Cauchy stress and
//    d stress / d strain. Finite-strain laws take the deformation gradient F and return the
//    first Piola-Kirchhoff stress P (row major, P[i * 3 + J]) and its derivative
//    dPdF[(i * 3 + J) * 9 + k * 3 + L] = dP_iJ / dF_kL. The element kernel asks
//    `kinematics()` which one to provide.
//  - Internal variables live per quadrature point in a flat array of `stateSize()` doubles:
//    `evaluate` reads the last converged state and writes the trial state; the problem commits
//    trial to converged after a load step converges, so a step cut restarts from the converged
//    state by construction.
//  - A law that cannot evaluate (a local return map that does not converge, J <= 0) sets
//    `failed` and a one-line `failure` instead of throwing: the kernel turns it into a named
//    step failure that step cutting can take over.
//  - Temperature: a law with a referenceTemperature() takes the prescribed temperature of its
//    block (MaterialInput::temperature, uniform over the block, a function of time), for its
//    thermal strain and its temperature-dependent parameters; without one it is at its
//    reference temperature. The temperature is data, not an unknown: tangents are at fixed T.
#include <array>
#include <cmath>
#include <optional>
#include <string>

namespace contactlab {

// The von Mises equivalent of a stress in Voigt order: sqrt(3 J2).
inline double vonMisesStress(const std::array<double, 6>& s) {
  return std::sqrt(0.5 * ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[2]) * (s[1] - s[2]) +
                          (s[2] - s[0]) * (s[2] - s[0])) +
                   3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

enum class Kinematics { SmallStrain, FiniteStrain };

struct MaterialInput {
  std::array<double, 6> strain{};  // small strain (Voigt, engineering shears)
  std::array<double, 9> F{};       // deformation gradient, row major (finite strain only)
  const double* stateOld = nullptr;
  // Prescribed temperature (degC); empty: the law's reference temperature, so that a model
  // without temperatures evaluates as an isothermal one, with no thermal strain.
  std::optional<double> temperature;
};

struct MaterialOutput {
  std::array<double, 6> stress{};    // Cauchy stress (Voigt) for small strain
  std::array<double, 36> tangent{};  // d stress / d strain, row major 6x6
  std::array<double, 9> P{};         // first Piola-Kirchhoff (finite strain only)
  std::array<double, 81> dPdF{};     // (finite strain only)
  double* stateNew = nullptr;
  // Plane stress (PlaneStress.hpp): the out-of-plane strain eps_zz (small strain) or stretch
  // F_zz (finite strain) the law solved for; empty otherwise (0 and 1 as the input said).
  std::optional<double> outOfPlane;
  bool failed = false;  // the law could not be evaluated; `failure` says why
  std::string failure;
};

class Material {
 public:
  virtual ~Material() = default;
  virtual std::string name() const = 0;
  virtual Kinematics kinematics() const = 0;
  virtual int stateSize() const { return 0; }
  virtual void initializeState(double* /*state*/) const {}
  virtual void evaluate(const MaterialInput& in, MaterialOutput& out) const = 0;
  // Density, for the mass matrix (the slow-dynamics regularization's inertia).
  virtual double density() const { return 0.0; }
  // Whether the tangent (d stress / d strain, or dP/dF with dP_iJ/dF_kL = dP_kL/dF_iJ) is
  // symmetric: true of every hyperelastic law and of associative plasticity with its consistent
  // tangent (tests/unit/materials check it); a non-associative law would say false.
  virtual bool symmetricTangent() const { return true; }
  // Whether the stress is C strain with C constant and no internal variables (at the reference
  // temperature): a small-strain element's force is then K u with K computed once, which the
  // problem keeps instead of integrating again (Problem::assemble).
  virtual bool linear() const { return false; }
  // Whether its inelastic flow preserves volume (J2 plasticity): fully integrated elements that
  // cannot change volume lock under it, which the automatic element technology avoids.
  virtual bool isochoricFlow() const { return false; }
  // Accumulated equivalent plastic strain of a state (0 for laws without plasticity): the
  // kernels output it and flag a point plastic when a step increased it.
  virtual double equivalentPlasticStrain(const double* /*state*/) const { return 0.0; }
  // The stress-free temperature of a law that takes a temperature (thermal strain, parameters
  // tabulated in T); empty for a law that ignores MaterialInput::temperature, which a scene
  // must not heat (every registered law takes one; test doubles need not).
  virtual std::optional<double> referenceTemperature() const { return std::nullopt; }
};

}  // namespace contactlab
