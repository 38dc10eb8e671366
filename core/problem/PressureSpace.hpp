#pragma once
// The discontinuous pressure space of one element and the L2 projection onto it, over the
// element's quadrature points with their measures (2 pi r dA in axisymmetry): degree 0, the
// constants (mean dilatation: Q1/P0), or degree 1, the polynomials linear in the coordinates
// the kernels pass: the reference cell's (xi), so the mapped P1 space of Q2/P1 and tet10/P1
// (deal.II's FE_DGPMonomial; on a curved cell it follows the cell, where a space linear in x
// does not and loses accuracy under plastic flow: doc/theory.md "The dilatation and its
// projection"), centred at their measure-weighted mean and scaled by their spread. A field f
// sampled at the points
// projects to coefficients c = M^-1 sum_q w_q psi(x_q) f_q and to values sum_i psi_i(x_q) c_i:
// coefficient(i) = sum_q weight(i, q) f_q, with weight(i, q) = sum_j (M^-1)_ij psi_j(x_q) w_q.
//
// A stack object set up per element (no allocation): the kernels that own one stay usable from
// several threads.
namespace contactlab {

class PressureSpace {
 public:
  static constexpr int kMaxPoints = 27;  // hex27's 3 x 3 x 3 rule, the largest a kernel uses
  static constexpr int kMaxSize = 4;

  // degree 0 or 1 in a cell of dimension dim (2 or 3).
  PressureSpace(int degree, int dim);

  int size() const { return size_; }
  // Throws std::invalid_argument, naming `kernel`, unless degree is 0 or 1 and a kernel of
  // numPoints quadrature points fits.
  static void checkKernel(const char* kernel, int degree, int numPoints);

  // Sets the element: numPoints quadrature points at `points` (3 coordinates each; unread for
  // degree 0, may be nullptr) with measures w (> 0). Throws std::invalid_argument when the Gram
  // matrix is singular.
  void setElement(int numPoints, const double* points, const double* measures);

  double basis(int q, int i) const { return psi_[q][i]; }
  double weight(int i, int q) const { return weight_[i][q]; }
  // The projection of f (one value per point) evaluated at point q.
  double projectedAt(int q, const double* f) const;

 private:
  int degree_;
  int dim_;
  int size_;
  int numPoints_ = 0;
  // Written by setElement over the element's points and the space's size (left unset beyond,
  // so that a kernel's evaluation does not clear them whole).
  double psi_[kMaxPoints][kMaxSize];
  double weight_[kMaxSize][kMaxPoints];
};

}  // namespace contactlab
