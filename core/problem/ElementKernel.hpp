#pragma once
// A solid element kernel: internal force f = dW/du and tangent K = df/du of one 2D (plane
// strain, per unit thickness; or axisymmetric, per full 360 degree ring) or 3D cell, for one
// kinematics. The small-strain kernel takes
// the linearized strain to the material; the total-Lagrangian kernel the deformation gradient.
// makeElementKernel picks one from the material's kinematics(), so blocks of both kinds live in
// one model and the next kernel is a new class.
//
// Array conventions: x holds 3 reference coordinates per node (z = 0 in 2D); u, residual and
// body forces hold dim() values per node (dof a * dim() + i); tangent is numDofs()^2 row major;
// material state is material.stateSize() doubles per quadrature point (nullptr allowed when 0).
//
// One kernel per element type and kinematics, shared by all its elements: shape functions at
// the quadrature points are tabulated at construction, and the const methods use only stack
// workspace, so one kernel may serve several threads. Invalid reference geometry throws
// InvalidElementError without the element's identity (the caller adds it with withLabel()); a
// material that cannot be evaluated or an element turned inside out by u throws
// ElementUpdateError naming the quadrature point.
#include "core/fem/QuadratureRule.hpp"
#include "core/materials/Material.hpp"
#include "core/mesh/ElementType.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace contactlab {

class ElementKernel {
 public:
  virtual ~ElementKernel() = default;

  ElementType type() const { return type_; }
  int dim() const { return dim_; }
  int numNodes() const { return numNodes_; }
  int numDofs() const { return dim_ * numNodes_; }
  int numQuadraturePoints() const { return numPoints_; }
  const QuadratureRule& rule() const { return *rule_; }
  virtual Kinematics kinematics() const = 0;

  // Calls material.initializeState for every quadrature point.
  void initializeState(const Material& material, double* state) const;

  // Internal force (the residual's element contribution) and, unless tangent is nullptr, its
  // derivative with respect to u. The tangent is symmetric when the material's is. The
  // temperature is the element's prescribed one, handed to the material
  // (MaterialInput::temperature; empty: the material's reference temperature).
  void compute(const double* x, const double* u, const Material& material, const double* stateOld,
               double* stateNew, double* residual, double* tangent,
               const std::optional<double>& temperature = std::nullopt) const {
    evaluate(x, u, material, stateOld, stateNew, residual, tangent, nullptr, nullptr, temperature);
  }

  // Cauchy stress (6 Voigt components, sigma_zz included in 2D) at each quadrature point
  // (6 * numQuadraturePoints(), may be nullptr) and/or its volume average over the reference
  // cell (6, may be nullptr), at the temperature as in compute().
  void stresses(const double* x, const double* u, const Material& material, const double* stateOld,
                double* stateNew, double* pointStress, double* averageStress,
                const std::optional<double>& temperature = std::nullopt) const {
    evaluate(x, u, material, stateOld, stateNew, nullptr, nullptr, pointStress, averageStress,
             temperature);
  }

  // Physical coordinates of the quadrature points, 3 per point.
  void quadraturePoints(const double* x, double* points) const;
  // Reference coordinates of the quadrature points, 3 per point (zeros beyond dim()).
  void referencePoints(double* points) const;
  // Quadrature weight times det J at each point (numQuadraturePoints() values).
  void pointMeasures(const double* x, double* measures) const;
  double volume(const double* x) const;

  // Equivalent nodal forces int N b dV of a body force per unit (reference) volume: constant
  // (dim() components) or a function of the position (x: 3 coordinates; writes dim()
  // components).
  void bodyForce(const double* x, const double* b, double* f) const;
  void bodyForce(const double* x, const std::function<void(const double* x, double* b)>& b,
                 double* f) const;

 protected:
  static constexpr int kMaxNodes = 27;

  // quadratureDegree < 0 selects stiffnessQuadratureDegree(type). Throws std::invalid_argument
  // for types that are not 2D or 3D cells, or for axisymmetric 3D cells. An axisymmetric
  // kernel's measures (gradients(), hence volume, body forces, stresses' averages) carry the
  // ring's 2 pi r: x is the radius, y the axis.
  ElementKernel(ElementType type, int quadratureDegree, bool axisymmetric = false);
  // The kernel's one pass over the quadrature points: each output that is not nullptr is
  // filled (residual, tangent, pointStress, averageStress as in compute() and stresses()).
  virtual void evaluate(const double* x, const double* u, const Material& material,
                        const double* stateOld, double* stateNew, double* residual, double* tangent,
                        double* pointStress, double* averageStress,
                        const std::optional<double>& temperature) const = 0;
  // Reference gradients at quadrature point q; returns det J times the weight (times 2 pi r_q
  // in axisymmetry).
  double gradients(int q, const double* x, double* dNdx) const;
  double measure(int q, const double* x) const;
  // Throws std::invalid_argument when the material is not of this kernel's kinematics or has
  // internal variables but no state arrays were given.
  void checkMaterial(const Material& material, const double* stateOld, double* stateNew) const;
  // The start of every evaluate(): checkMaterial, then the outputs that are accumulated over the
  // quadrature points (residual, tangent, averageStress; each when not nullptr) set to zero.
  void beginEvaluation(const Material& material, const double* stateOld, double* stateNew,
                       double* residual, double* tangent, double* averageStress) const;
  // The small-strain kernels' step at quadrature point q (measure w), once in.strain is set:
  // the material evaluated with point q's state slices (ElementUpdateError when it fails), its
  // stress recorded into pointStress and added, weighted, to averageStress and `volume` (each
  // when not nullptr).
  void evaluateSmallStrainPoint(int q, double w, const Material& material, const double* stateOld,
                                double* stateNew, MaterialInput& in, MaterialOutput& out,
                                double* pointStress, double* averageStress, double& volume) const;
  // The finite-strain kernels' step at quadrature point q, once in.F is set: det F > 0 checked
  // (else ElementUpdateError "inverted-element"), the material evaluated with point q's state
  // slices, and the Cauchy stress P F^T / det F recorded as in evaluateSmallStrainPoint.
  void evaluateFiniteStrainPoint(int q, double w, const Material& material, const double* stateOld,
                                 double* stateNew, MaterialInput& in, MaterialOutput& out,
                                 double* pointStress, double* averageStress, double& volume) const;
  // The ring kernels' accumulation at one quadrature point of weight w, for an operator B of
  // `rows` rows (B[r][k]: d(measure slots[r]) / du_k over nd dofs) and the material's response
  // in those slots: residual += w B^T s (s[slots[r]]) and, unless tangent is nullptr,
  // tangent += w B^T C B (C[slots[r] * ldC + slots[m]], as given: unsymmetric or not).
  static void addOperatorTerms(int rows, const int* slots, const double (*B)[kMaxNodes * 2], int nd,
                               double w, const double* s, const double* C, int ldC,
                               double* residual, double* tangent);
  // Copies the strictly upper blocks K_ab (b > a, dim x dim each) of a numDofs()^2 row-major
  // tangent onto K_ba^T, adding to what is there: the kernels accumulate only the blocks
  // b >= a of a symmetric tangent.
  template <int D>
  void addMirroredUpperBlocks(double* tangent) const {
    const int n = numNodes_, nd = D * n;
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        for (int i = 0; i < D; ++i)
          for (int k = 0; k < D; ++k)
            tangent[(b * D + k) * nd + a * D + i] += tangent[(a * D + i) * nd + b * D + k];
  }

  ElementType type_;
  int dim_;
  int numNodes_;
  int numPoints_;
  bool axisymmetric_;
  const QuadratureRule* rule_;
  std::vector<double> N_;      // N_[q * numNodes + a]
  std::vector<double> dNdxi_;  // dNdxi_[(q * numNodes + a) * dim + j]
};

// The kernel of `type` for materials of `kinematics`; `axisymmetric` (2D only, else
// std::invalid_argument) the ring kernels AxisymmetricKernel and
// AxisymmetricTotalLagrangianKernel.
std::unique_ptr<ElementKernel> makeElementKernel(ElementType type, Kinematics kinematics,
                                                 int quadratureDegree = -1,
                                                 bool axisymmetric = false);

}  // namespace contactlab
