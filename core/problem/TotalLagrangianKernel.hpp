#pragma once
// Total-Lagrangian solid element for finite-strain materials: with the deformation gradient
// F = I + grad_X u on the reference configuration and the material's first Piola-Kirchhoff
// stress P(F),
//   f_(a i) = int_Omega0 P_iJ dN_a/dX_J dV,
//   K_(a i)(b k) = int_Omega0 dN_a/dX_J (dP_iJ/dF_kL) dN_b/dX_L dV,
// so the geometric stiffness (delta_ik S_JL) is part of dP/dF and comes from the material.
// 2D is plane strain per unit reference thickness (F_zz = 1). Conventions of ElementKernel.hpp;
// det F <= 0 at a quadrature point throws ElementUpdateError("inverted-element").
#include "core/problem/DimensionTemplatedKernel.hpp"

namespace contactlab {

class TotalLagrangianKernel : public DimensionTemplatedKernel<TotalLagrangianKernel> {
 public:
  explicit TotalLagrangianKernel(ElementType type, int quadratureDegree = -1)
      : DimensionTemplatedKernel(type, quadratureDegree) {}

  Kinematics kinematics() const override { return Kinematics::FiniteStrain; }

 private:
  friend class DimensionTemplatedKernel<TotalLagrangianKernel>;
  // Stresses are Cauchy, sigma = P F^T / det F; the average is over the reference cell.
  template <int D>
  void evaluateIn(const double* x, const double* u, const Material& material,
                  const double* stateOld, double* stateNew, double* residual, double* tangent,
                  double* pointStress, double* averageStress,
                  const std::optional<double>& temperature) const;
};

}  // namespace contactlab
