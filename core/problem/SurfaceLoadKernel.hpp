#pragma once
// Equivalent nodal forces of surface loads on a facet. Dead loads act on the undeformed
// geometry: f_a = int N_a t dA for a traction t (force per area), and t = -p n for a pressure p,
// with n the facet normal of IsoparametricMap.hpp (right-hand rule on gmsh's node order in 3D,
// (t_y, -t_x) in 2D: outward on counter-clockwise boundaries, so positive p pushes inward).
// A follower pressure acts on the deformed facet (finite strain): f_a = -p int N_a n da over
// the current positions, with its derivative (the load stiffness) for Newton's tangent.
//
// Facets: line2/line3 in 2D (per unit thickness), tri3/tri6/quad4/quad8/quad9 in 3D. x holds
// 3 coordinates per node; f holds spaceDim() values per node. The default quadrature degree,
// 2 * order + 1, integrates a constant pressure exactly even on curved facets.
// Axisymmetric (2D, x the radius): dA = 2 pi r ds, the load on the whole ring
// (AxisymmetricKernel.hpp); a follower pressure there acts on the current ring, 2 pi r ds at the
// current radius r = x + u_x.
#include "core/fem/QuadratureRule.hpp"
#include "core/mesh/ElementType.hpp"

#include <functional>
#include <vector>

namespace contactlab {

class SurfaceLoadKernel {
 public:
  // spaceDim must be the facet's dimension + 1 (2 for lines, 3 for surfaces): otherwise, or for
  // a type that is not a line or surface, or axisymmetric in 3D, throws std::invalid_argument.
  // quadratureDegree < 0 selects 2 * order + 1.
  SurfaceLoadKernel(ElementType facetType, int spaceDim, int quadratureDegree = -1,
                    bool axisymmetric = false);

  ElementType type() const { return type_; }
  int spaceDim() const { return spaceDim_; }
  int numNodes() const { return numNodes_; }
  int numDofs() const { return spaceDim_ * numNodes_; }
  const QuadratureRule& rule() const { return *rule_; }

  double area(const double* x) const;

  // Traction: constant (spaceDim() components) or a function of the position (3 coordinates;
  // writes spaceDim() components).
  void traction(const double* x, const double* t, double* f) const;
  void traction(const double* x, const std::function<void(const double* x, double* t)>& t,
                double* f) const;
  // Pressure: constant or a function of the position.
  void pressure(const double* x, double p, double* f) const;
  void pressure(const double* x, const std::function<double(const double* x)>& p, double* f) const;
  // Follower pressure p on the facet at its current position x + u (u: spaceDim() values per
  // node): f_a = -p int N_a n da, where n da = (dx/dxi_0 x dx/dxi_1) dxi in 3D and
  // (dy/dxi, -dx/dxi) dxi per unit thickness in 2D (Nanson's formula on the facet), times
  // 2 pi r at the current radius on an axisymmetric facet. Unless
  // dfdu is nullptr, also its derivative dfdu[(a * spaceDim() + i) * numDofs() + b *
  // spaceDim() + k] = df_(a i) / du_(b k): the load stiffness, which is not symmetric in
  // general. At u = 0 the force equals pressure(x, p, f). A facet that the displacement
  // collapses is not an error here (n da vanishes); its element kernel reports it.
  void followerPressure(const double* x, const double* u, double p, double* f, double* dfdu) const;

 private:
  // Calls visit(q, point, normal, weight * dA) at every quadrature point.
  template <class Visit>
  void forEachPoint(const double* x, Visit&& visit) const;

  ElementType type_;
  int spaceDim_;
  int numNodes_;
  bool axisymmetric_;
  const QuadratureRule* rule_;
  std::vector<double> N_;      // N_[q * numNodes + a]
  std::vector<double> dNdxi_;  // dNdxi_[(q * numNodes + a) * (spaceDim - 1) + j]
};

}  // namespace contactlab
