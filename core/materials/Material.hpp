#pragma once
// Constitutive law at one quadrature point.
//
// Conventions (fixed for the whole project):
//  - Voigt order xx, yy, zz, xy, yz, xz; strains use engineering shears (gamma = 2 eps).
//  - Plane strain is the 3D law with eps_zz = eps_yz = eps_xz = 0; the 2D kernels pick the
//    rows/columns {0, 1, 3} and still report sigma_zz.
//  - Small-strain laws take the linearized strain; finite-strain laws (later) take the
//    deformation gradient F and return the first Piola-Kirchhoff stress P and dP/dF. The
//    element kernel asks `kinematics()` which one to provide.
//  - Internal variables live per quadrature point in a flat array of `stateSize()` doubles:
//    `evaluate` reads the last converged state and writes the trial state; the problem commits
//    trial to converged after a load step converges.
#include <array>
#include <string>

namespace contactlab {

enum class Kinematics { SmallStrain, FiniteStrain };

struct MaterialInput {
  std::array<double, 6> strain{};  // small strain (Voigt, engineering shears)
  std::array<double, 9> F{};       // deformation gradient, row major (finite strain only)
  const double* stateOld = nullptr;
};

struct MaterialOutput {
  std::array<double, 6> stress{};    // Cauchy stress (Voigt) for small strain
  std::array<double, 36> tangent{};  // d stress / d strain, row major 6x6
  std::array<double, 9> P{};         // first Piola-Kirchhoff (finite strain only)
  std::array<double, 81> dPdF{};     // (finite strain only)
  double* stateNew = nullptr;
};

class Material {
 public:
  virtual ~Material() = default;
  virtual std::string name() const = 0;
  virtual Kinematics kinematics() const = 0;
  virtual int stateSize() const { return 0; }
  virtual void initializeState(double* /*state*/) const {}
  virtual void evaluate(const MaterialInput& in, MaterialOutput& out) const = 0;
  // Density, for body forces and (later) slow-dynamics mass.
  virtual double density() const { return 0.0; }
};

}  // namespace contactlab
