#pragma once
// Element mass matrix of a 2D or 3D cell: M_(a i)(b j) = rho int N_a N_b dV delta_ij, with a
// rule exact for N_a N_b on affine cells (degree 2 * order). Lumped: HRZ (Hinton, Rock,
// Zienkiewicz 1976), the consistent diagonal scaled to the element's total mass, positive for
// quadratic elements too (row sums are not: a tri6 or tet10 corner gets zero or negative mass).
// Layout: numDofs()^2 row major, dof a * dim + i, as SmallStrainKernel. Axisymmetric (2D):
// dV = 2 pi r dA, the ring's mass (AxisymmetricKernel.hpp).
#include "core/fem/QuadratureRule.hpp"
#include "core/mesh/ElementType.hpp"

#include <vector>

namespace contactlab {

class MassKernel {
 public:
  explicit MassKernel(ElementType type, bool axisymmetric = false);
  int numDofs() const { return dim_ * numNodes_; }
  // Adds rho * M_e (consistent or lumped) to `mass`. Throws InvalidElementError when inverted.
  void add(const double* x, double density, bool lumped, double* mass) const;

 private:
  int dim_;
  int numNodes_;
  bool axisymmetric_;
  const QuadratureRule* rule_;
  std::vector<double> N_, dNdxi_;
};

}  // namespace contactlab
