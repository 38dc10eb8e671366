#pragma once
// Small-strain axisymmetric solid element: a 2D cell in the (r, z) half-plane, r = x >= 0 the
// radius and z = y the axis (Abaqus CAX, code_aster AXIS), standing for the ring it sweeps
// about the y axis. Strains (Voigt slots of Material.hpp):
//   eps_rr = du_r/dr (xx), eps_zz = du_z/dz (yy), eps_tt = u_r / r (zz: the hoop strain, the
//   out-of-plane normal strain of a 2D model), gamma_rz = du_r/dz + du_z/dr (xy),
// so the 3D small-strain materials apply unchanged, and the zz stress is the hoop stress
// sigma_tt. Integrals are over the whole ring (dV = 2 pi r dA): forces, reactions and energies
// are per full 360 degrees, as Abaqus's CAX elements report them. Quadrature points are inside
// the cell, so r > 0 there even when nodes lie on the axis (their u_r must be held at 0 by a
// Dirichlet condition: Problem refuses a model that does not). Conventions of ElementKernel.hpp.
#include "core/problem/ElementKernel.hpp"

namespace contactlab {

class AxisymmetricKernel : public ElementKernel {
 public:
  // Throws std::invalid_argument for a type that is not a 2D cell. quadratureDegree < 0
  // selects defaultQuadratureDegree(type).
  explicit AxisymmetricKernel(ElementType type, int quadratureDegree = -1)
      : ElementKernel(type, quadratureDegree < 0 ? defaultQuadratureDegree(type) : quadratureDegree,
                      true) {}

  // One degree above the plane kernel's (the 2 pi r in the measure raises the integrand's
  // degree by one), and at least 2: tri3's one-point rule would leave a spurious zero-energy
  // mode (u_r = z - z_c, u_z = -r, the rotation about the centroid, strain-free there).
  static int defaultQuadratureDegree(ElementType type) {
    const int plane = stiffnessQuadratureDegree(type) + 1;
    return plane < 2 ? 2 : plane;
  }

  Kinematics kinematics() const override { return Kinematics::SmallStrain; }

 private:
  void evaluate(const double* x, const double* u, const Material& material, const double* stateOld,
                double* stateNew, double* residual, double* tangent, double* pointStress,
                double* averageStress, const std::optional<double>& temperature) const override;
};

}  // namespace contactlab
