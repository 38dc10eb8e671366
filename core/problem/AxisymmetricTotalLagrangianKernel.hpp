#pragma once
// Total-Lagrangian axisymmetric solid element for finite-strain materials: a 2D cell in the
// (R, Z) half-plane of the reference configuration (x = R >= 0, y = Z the axis), standing for
// its ring, as AxisymmetricKernel. The deformation gradient is
//   F = [[1 + du_r/dR, du_r/dZ, 0], [du_z/dR, 1 + du_z/dZ, 0], [0, 0, 1 + u_r/R]]
// (F_tt the hoop stretch r/R), and with the material's first Piola-Kirchhoff stress P(F)
//   f_(a i) = int P : dF/du_(a i) dV0,  K = int (dF/du)^T (dP/dF) (dF/du) dV0,  dV0 = 2 pi R dA,
// where dF/du_(a r) has dN_a/dX_J in row r and N_a / R in the tt slot. Stresses are Cauchy
// (sigma = P F^T / det F, the hoop stress in the zz slot), averaged over the reference ring.
// det F <= 0 at a quadrature point throws ElementUpdateError("inverted-element").
#include "core/problem/AxisymmetricKernel.hpp"

namespace contactlab {

class AxisymmetricTotalLagrangianKernel : public ElementKernel {
 public:
  // Throws std::invalid_argument for a type that is not a 2D cell; quadratureDegree < 0
  // selects AxisymmetricKernel::defaultQuadratureDegree(type).
  explicit AxisymmetricTotalLagrangianKernel(ElementType type, int quadratureDegree = -1)
      : ElementKernel(type,
                      quadratureDegree < 0 ? AxisymmetricKernel::defaultQuadratureDegree(type)
                                           : quadratureDegree,
                      true) {}

  Kinematics kinematics() const override { return Kinematics::FiniteStrain; }

 private:
  void evaluate(const double* x, const double* u, const Material& material, const double* stateOld,
                double* stateNew, double* residual, double* tangent, double* pointStress,
                double* averageStress, const std::optional<double>& temperature) const override;
};

}  // namespace contactlab
