#pragma once
// Small-strain solid element: internal force f = int B^T sigma dV and tangent K = int B^T C B dV
// for 3D cells and 2D plane strain (per unit thickness; Voigt rows {0, 1, 3} of Material.hpp).
//
// Array conventions: x holds 3 coordinates per node (z = 0 in 2D); u, residual and body forces
// hold dim() values per node (dof a * dim() + i); tangent is numDofs()^2 row major; material
// state is material.stateSize() doubles per quadrature point (nullptr allowed when 0).
//
// One kernel per element type, shared by all its elements: shape functions at the quadrature
// points are tabulated at construction, and the const methods use only stack workspace, so
// one kernel may serve several threads. Invalid geometry throws InvalidElementError without the
// element's identity: the caller adds it with withLabel().
#include "core/fem/QuadratureRule.hpp"
#include "core/materials/Material.hpp"
#include "core/mesh/ElementType.hpp"

#include <functional>
#include <vector>

namespace contactlab {

class SolidKernel {
 public:
  // quadratureDegree < 0 selects stiffnessQuadratureDegree(type). Throws std::invalid_argument
  // for types that are not 2D or 3D cells.
  explicit SolidKernel(ElementType type, int quadratureDegree = -1);

  ElementType type() const { return type_; }
  int dim() const { return dim_; }
  int numNodes() const { return numNodes_; }
  int numDofs() const { return dim_ * numNodes_; }
  int numQuadraturePoints() const { return numPoints_; }
  const QuadratureRule& rule() const { return *rule_; }

  // Calls material.initializeState for every quadrature point.
  void initializeState(const Material& material, double* state) const;

  // Internal force (the residual's element contribution) and, unless tangent is nullptr, its
  // derivative with respect to u. The tangent is symmetric when the material's is.
  void compute(const double* x, const double* u, const Material& material, const double* stateOld,
               double* stateNew, double* residual, double* tangent) const;

  // Cauchy stress (6 Voigt components, sigma_zz included in 2D) at each quadrature point
  // (6 * numQuadraturePoints(), may be nullptr) and/or its volume average (6, may be nullptr).
  void stresses(const double* x, const double* u, const Material& material, const double* stateOld,
                double* stateNew, double* pointStress, double* averageStress) const;

  // Physical coordinates of the quadrature points, 3 per point.
  void quadraturePoints(const double* x, double* points) const;

  double volume(const double* x) const;

  // Equivalent nodal forces int N b dV of a body force per unit volume: constant (dim()
  // components) or a function of the position (x: 3 coordinates; writes dim() components).
  void bodyForce(const double* x, const double* b, double* f) const;
  void bodyForce(const double* x, const std::function<void(const double* x, double* b)>& b,
                 double* f) const;

 private:
  template <int D>
  void computeImpl(const double* x, const double* u, const Material& material,
                   const double* stateOld, double* stateNew, double* residual, double* tangent,
                   double* pointStress, double* averageStress) const;
  template <int D>
  void accumulateTangent(const double* C6, double w, const double* dNdx, double* CB, double* SB,
                         double* tangent) const;
  // Physical gradients at quadrature point q; returns det J times the weight.
  double gradients(int q, const double* x, double* dNdx) const;
  double measure(int q, const double* x) const;

  ElementType type_;
  int dim_;
  int numNodes_;
  int numPoints_;
  const QuadratureRule* rule_;
  std::vector<double> N_;      // N_[q * numNodes + a]
  std::vector<double> dNdxi_;  // dNdxi_[(q * numNodes + a) * dim + j]
};

}  // namespace contactlab
