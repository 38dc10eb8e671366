#pragma once
// The finite-strain three-field (u, p, theta) element with p and theta discontinuous and
// condensed (Simo, Taylor & Pister 1985, Comput. Methods Appl. Mech. Eng. 51, 177-208: Q1/P0,
// the mean dilatation; with linear pressures Q2/P1, tet10/P1). The material sees
//   F_bar = alpha F,  alpha = (theta_bar / J)^(1/n),  theta_bar = Pi(J),
// Pi the L2 projection on the element's pressure space (PressureSpace), n = 3 in 3D and
// axisymmetry and 2 in plane strain (only the in-plane components scaled). With p and theta in
// the same discontinuous space the constraint theta = Pi(J) holds exactly and the pressure is
// its multiplier, so the condensed element is the displacement element of the energy
// int W(F_bar(u)) dV: f = int P(F_bar) : dF_bar/du dV and K its exact second derivative,
// symmetric whenever the material's dP/dF is (unlike F-bar's). Same quadrature as the
// full-integration kernel of the geometry; conventions of ElementKernel.hpp.
#include "core/problem/PlanarOrRingKernel.hpp"

namespace contactlab {

class ProjectedJacobianKernel : public PlanarOrRingKernel<ProjectedJacobianKernel> {
 public:
  // pressureDegree 0 or 1; axisymmetric for the ring (2D types only).
  ProjectedJacobianKernel(ElementType type, int pressureDegree, bool axisymmetric,
                          int quadratureDegree = -1);

  Kinematics kinematics() const override { return Kinematics::FiniteStrain; }
  int pressureDegree() const { return pressureDegree_; }

 private:
  friend class PlanarOrRingKernel<ProjectedJacobianKernel>;
  // Plane strain and 3D, written per dimension (the total-Lagrangian kernel's products).
  template <int D>
  void evaluatePlanar(const double* x, const double* u, const Material& material,
                      const double* stateOld, double* stateNew, double* residual, double* tangent,
                      double* pointStress, double* averageStress,
                      const std::optional<double>& temperature) const;
  // The ring (axisymmetric), through the run-time SlotOperator: its hoop row.
  void evaluateRing(const double* x, const double* u, const Material& material,
                    const double* stateOld, double* stateNew, double* residual, double* tangent,
                    double* pointStress, double* averageStress,
                    const std::optional<double>& temperature) const;

  int pressureDegree_;
};

}  // namespace contactlab
