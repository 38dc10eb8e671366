#pragma once
// A small-strain element whose dilatation is the L2 projection of tr eps on a discontinuous
// pressure space of the element (PressureSpace): with the constants it is B-bar, the mean
// dilatation of Hughes (1980) and Nagtegaal, Parks & Rice (1974); with the linear polynomials
// it is the three-field (u, p, theta) element with p and theta discontinuous and condensed
// (Q2/P1, tet10/P1; Simo & Hughes, Computational Inelasticity, 1998, section 4.4), which for a
// discontinuous pressure space is this same modified-strain element. The material sees
//   eps_bar = eps + (theta_bar - tr eps) m / n,   theta_bar = Pi(tr eps),
// m the diagonal slots (n = 3 in 3D and axisymmetry, where the hoop strain
// enters the dilatation, and 2 in plane strain, whose out-of-plane strain stays 0), and the
// element is f = int B_bar^T sigma(eps_bar) dV, K = int B_bar^T C B_bar dV: the consistent
// tangent, symmetric when C is, constant for a linear law (so the problem keeps it).
// Every quadrature point is evaluated at the same rule as the full-integration kernel of the
// geometry. Conventions of ElementKernel.hpp.
#include "core/problem/PlanarOrRingKernel.hpp"

namespace contactlab {

class ProjectedDilatationKernel : public PlanarOrRingKernel<ProjectedDilatationKernel> {
 public:
  // pressureDegree 0 (B-bar) or 1; axisymmetric for the ring (2D types only). quadratureDegree
  // < 0: the full-integration kernel's rule.
  ProjectedDilatationKernel(ElementType type, int pressureDegree, bool axisymmetric,
                            int quadratureDegree = -1);

  Kinematics kinematics() const override { return Kinematics::SmallStrain; }
  int pressureDegree() const { return pressureDegree_; }

 private:
  friend class PlanarOrRingKernel<ProjectedDilatationKernel>;
  // Plane strain and 3D, written per dimension, and the ring (its hoop row): both through
  // evaluateCell on the full-integration kernels' products (SmallStrainProducts.hpp).
  template <int D>
  void evaluatePlanar(const double* x, const double* u, const Material& material,
                      const double* stateOld, double* stateNew, double* residual, double* tangent,
                      double* pointStress, double* averageStress,
                      const std::optional<double>& temperature) const;
  void evaluateRing(const double* x, const double* u, const Material& material,
                    const double* stateOld, double* stateNew, double* residual, double* tangent,
                    double* pointStress, double* averageStress,
                    const std::optional<double>& temperature) const;
  template <class Cell, class Cells>
  void evaluateCell(const Cells& cells, const double* x, const double* u, const Material& material,
                    const double* stateOld, double* stateNew, double* residual, double* tangent,
                    double* pointStress, double* averageStress,
                    const std::optional<double>& temperature) const;

  int pressureDegree_;
};

// The quadrature degree of the full-integration kernel of `type` (the ring's in axisymmetry):
// the technologies keep its rule, so that a block's internal variables keep their layout.
int fullIntegrationDegree(ElementType type, bool axisymmetric);

}  // namespace contactlab
