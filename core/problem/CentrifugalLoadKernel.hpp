#pragma once
// One element's share of a centrifugal load (CentrifugalLoad in Loads.hpp): the equivalent
// nodal forces f_(a i) = rho omega^2 s(t) sum_b M_ab P_ij (x_b - c)_j and, for a follower load,
// the load stiffness -df/du = -rho omega^2 s(t) M_ab P_ij, from the element's consistent mass
// matrix M of unit density (MassKernel: exact for N_a N_b on affine cells, so the force is the
// exact integral of N_a rho omega^2 P (x - c) wherever x is interpolated by the shape
// functions). Layouts as ElementKernel: dim values per node, matrices numDofs^2 row major.
#include "core/problem/Loads.hpp"

#include <array>

namespace contactlab {

class CentrifugalLoadKernel {
 public:
  // Throws std::invalid_argument for a zero axis, a plane 2D model whose axis is not z, or an
  // axisymmetric one (SolidModel::axisymmetric) whose axis is not its symmetry axis, the y axis
  // through x = 0 (then P (x - c) is the radius vector (r, 0) and M carries the ring's 2 pi r).
  CentrifugalLoadKernel(const CentrifugalLoad& load, int dim, bool axisymmetric = false);

  // f += the forces for nodal positions `x` (3 per node: reference, or current for a follower
  // load), `mass` the element's unit-density consistent mass (numNodes * dim squared).
  void addForce(const double* mass, const double* x, int numNodes, double t, double* f) const;
  // k += -df/du of a follower load.
  void addStiffness(const double* mass, int numNodes, double t, double* k) const;

 private:
  double intensity(double t) const;  // rho omega^2 s(t)

  const CentrifugalLoad& load_;
  int dim_;
  std::array<double, 9> projector_{};  // P = I - a a^T, dim x dim row major (stride 3)
};

}  // namespace contactlab
