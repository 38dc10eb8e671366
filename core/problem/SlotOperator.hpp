#pragma once
// The linear map from an element's nodal displacements to the components ("slots") of a
// kinematic quantity at one quadrature point, as the element technologies use it: the small
// strain (Voigt slots, engineering shears) or the displacement part of the deformation gradient
// (slots of F, row major 3 x 3). Rows are the slots the cell's geometry moves:
//   small strain   3D: xx yy zz xy yz xz   plane strain: xx yy xy   axisymmetric: rr zz tt rz
//   F              3D: all nine            plane strain: xx xy yx yy  axisymmetric: rr rz zr zz tt
// (axisymmetric: x = r, y = z the axis, the third direction the hoop; tt = u_r / r, or
// F_tt = 1 + u_r / R). Dof k = a * dim + c of node a, component c; a column of B has nonzeros only
// in the rows componentRows[c] list, which the products below skip to.
//
// The volumetric rows are the diagonal ones, xx yy zz in 3D, xx yy in plane strain (the
// out-of-plane direction stays unstretched), rr zz tt in axisymmetry: their sum is the small
// strain's dilatation, and scaling every row of F by alpha multiplies det F by
// alpha^volumetricCount.
#include "core/mesh/ElementType.hpp"

#include <array>

namespace contactlab {

struct SlotOperator {
  static constexpr int kMaxRows = 9;
  static constexpr int kMaxDofs = 81;

  int rows = 0;
  int dim = 0;
  int numDofs = 0;
  int slot[kMaxRows] = {};       // index in the material's array (6 Voigt or 9 F components)
  int componentRows[3][3] = {};  // rows where a column of component c may be nonzero
  int componentRowCount[3] = {};
  int volumetricCount = 0;         // n: the dimension of the dilatation
  bool volumetric[kMaxRows] = {};  // the diagonal rows
  // Rows x numDofs set (zeros included) by the operator functions below; left unset beyond.
  double B[kMaxRows][kMaxDofs];

  // slots = B u.
  void apply(const double* u, double* values) const;
  // out += scale * B^T v (v over the rows).
  void addTransposeProduct(const double* v, double scale, double* out) const;
  // K += B^T (w C) B, C a rows x rows matrix (row major). upperBlocks: only the node blocks b >= a
  // of K (rows a * dim .., columns from a * dim on), for a symmetric product mirrored later by
  // mirrorUpperBlocks.
  void addProduct(const double* C, double w, double* K, bool upperBlocks) const;
};

// The small-strain operator of a cell of `numNodes` nodes at a quadrature point: dNdx physical
// gradients (dim per node), N the shape values and r the point's radius (axisymmetric only).
void smallStrainOperator(int dim, bool axisymmetric, int numNodes, const double* N,
                         const double* dNdx, double r, SlotOperator& op);
// dF/du of a cell (reference gradients dNdX; R the point's reference radius in axisymmetry).
void deformationGradientOperator(int dim, bool axisymmetric, int numNodes, const double* N,
                                 const double* dNdX, double R, SlotOperator& op);

// The op.rows x op.rows restriction of a material's matrix: out[r][m] = M[slot[r] * ld + slot[m]].
void restrictToSlots(const SlotOperator& op, const double* M, int ld, double* out);

// F = I + B u in the operator's slots (a deformationGradientOperator's), identity elsewhere.
std::array<double, 9> deformationGradient(const SlotOperator& op, const double* u);
// g[r] = d ln det F / dF_slot(r) = (F^-T)_slot(r), from Finv = F^-1.
void logJacobianGradient(const SlotOperator& op, const std::array<double, 9>& Finv, double* g);
// L[r * rows + m] = d^2 ln det F / dF_s dF_t = -(F^-1)_Jk (F^-1)_Li for s = slot(r) = (i, J),
// t = slot(m) = (k, L): symmetric.
void logJacobianHessian(const SlotOperator& op, const std::array<double, 9>& Finv, double* L);

// K += x y^T over nd x nd (upperBlocks as in addProduct, node blocks of `dim` dofs).
void addOuterProduct(const double* x, const double* y, double scale, int nd, int dim, double* K,
                     bool upperBlocks);
// Copies the strictly upper node blocks K_ab (b > a) onto K_ba^T, adding to what is there.
void mirrorUpperBlocks(int nd, int dim, double* K);

}  // namespace contactlab
