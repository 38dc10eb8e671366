#pragma once
// The deformation gradient of a 2D (plane strain, F_zz = 1) or 3D cell at one quadrature point
// and its products, written per dimension D at compile time: those of the total-Lagrangian
// kernel (TotalLagrangianKernel) and of the technologies that modify its F (FBarKernel). n
// nodes, dNdX the reference gradients (D per node), dof a * D + i. Tensors are row-major 3 x 3
// (P_iJ at i * 3 + J), dP/dF 9 x 9 (dP_iJ/dF_kL at (i * 3 + J) * 9 + k * 3 + L); in plane strain
// only their in-plane components are read. Defined here, so that each kernel inlines them.
#include <array>

namespace contactlab {

// F = I + grad_X u.
template <int D>
inline std::array<double, 9> deformationGradientOf(int n, const double* dNdX, const double* u) {
  std::array<double, 9> F = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < D; ++i)
      for (int J = 0; J < D; ++J)
        F[i * 3 + J] += u[a * D + i] * dNdX[a * D + J];
  return F;
}

// out_(a i) += w sum_J T_iJ dN_a/dX_J: B^T T for a tensor T (the internal force when T = P).
template <int D>
inline void addGradientTransposeProduct(int n, const double* dNdX, const double* T, double w,
                                        double* out) {
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < D; ++i) {
      double f = 0.0;
      for (int J = 0; J < D; ++J)
        f += T[i * 3 + J] * dNdX[a * D + J];
      out[a * D + i] += w * f;
    }
}

// tangent (nd x nd, nd = D n) += w B^T A B, K_(a i)(b k) = w dN_a/dX_J A_iJkL dN_b/dX_L: every
// block, or (upperOnly, for an A with the major symmetry) the blocks b >= a, which
// addMirroredUpperBlocks completes. AB is a work array of D D nd doubles.
template <int D>
inline void addGradientTangent(int n, const double* dNdX, const double* A, double w, double* AB,
                               double* tangent, bool upperOnly) {
  const int nd = D * n;
  // AB[(i D + J) nd + b D + k] = w sum_L A_iJkL dN_b/dX_L: the tangent's rows are then D fused
  // rows of AB, which vectorize.
  for (int i = 0; i < D; ++i)
    for (int J = 0; J < D; ++J) {
      double* row = &AB[(i * D + J) * nd];
      const double* Ai = &A[(i * 3 + J) * 9];
      for (int b = 0; b < n; ++b)
        for (int k = 0; k < D; ++k) {
          double s = 0.0;
          for (int L = 0; L < D; ++L)
            s += Ai[k * 3 + L] * dNdX[b * D + L];
          row[b * D + k] = w * s;
        }
    }
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < D; ++i) {
      double* row = &tangent[(a * D + i) * nd];
      const double* g = &dNdX[a * D];
      const double* m0 = &AB[(i * D) * nd];
      const double* m1 = &AB[(i * D + 1) * nd];
      const int first = upperOnly ? a * D : 0;
      if constexpr (D == 2) {
        for (int c = first; c < nd; ++c)
          row[c] += g[0] * m0[c] + g[1] * m1[c];
      } else {
        const double* m2 = &AB[(i * D + 2) * nd];
        for (int c = first; c < nd; ++c)
          row[c] += g[0] * m0[c] + g[1] * m1[c] + g[2] * m2[c];
      }
    }
}

}  // namespace contactlab
