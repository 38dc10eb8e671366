#pragma once
// The F-bar element of de Souza Neto, Peric, Dutko & Owen (1996, Int. J. Solids Struct. 33,
// 3277-3296) for quad4 and hex8 cells (and the quad4 ring): the material sees
//   F_bar = alpha F,  alpha = (J0 / J)^(1/n),
// J0 = det F at the cell's centre, n = 3 in 3D and axisymmetry and 2 in plane strain (where
// only the in-plane components are scaled, so that F_zz stays 1): the volume change is
// constant over the cell and the element does not lock under isochoric plastic flow or near
// incompressibility. Its internal force is the virtual work of the Cauchy stress sigma(F_bar)
// on the current cell, f = int J sigma_bar : grad_x(delta u) dV = int alpha^(1 - n) P(F_bar) :
// delta F dV, and the tangent is its exact derivative (through J0 too): NOT symmetric, even for
// a hyperelastic law, since the formulation is not the gradient of an energy. Same quadrature
// as the full-integration kernel of the geometry; conventions of ElementKernel.hpp.
#include "core/problem/PlanarOrRingKernel.hpp"

#include <vector>

namespace contactlab {

class FBarKernel : public PlanarOrRingKernel<FBarKernel> {
 public:
  // type quad4 or hex8 (std::invalid_argument otherwise); axisymmetric for the ring.
  FBarKernel(ElementType type, bool axisymmetric, int quadratureDegree = -1);

  Kinematics kinematics() const override { return Kinematics::FiniteStrain; }

 private:
  friend class PlanarOrRingKernel<FBarKernel>;
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

  std::vector<double> centreN_;      // shape values at the cell's centre
  std::vector<double> centreDNdxi_;  // and their reference derivatives
};

}  // namespace contactlab
