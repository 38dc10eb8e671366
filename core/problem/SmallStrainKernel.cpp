#include "core/problem/SmallStrainKernel.hpp"

namespace contactlab {
namespace {

// Voigt index of the tensor component (i, j): full 3D, and 2D within the plane-strain rows.
constexpr int kVoigt3[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};
constexpr int kVoigt2[2][2] = {{0, 2}, {2, 1}};
constexpr int kPlaneRows[3] = {0, 1, 3};

template <int D>
constexpr int voigt(int i, int j) {
  return D == 3 ? kVoigt3[i][j] : kVoigt2[i][j];
}

}  // namespace

template <int D>
void SmallStrainKernel::evaluateIn(const double* x, const double* u, const Material& material,
                                   const double* stateOld, double* stateNew, double* residual,
                                   double* tangent, double* pointStress, double* averageStress,
                                   const std::optional<double>& temperature) const {
  constexpr int V = D == 2 ? 3 : 6;  // Voigt components carried by the element
  const int n = numNodes_;
  beginEvaluation(material, stateOld, stateNew, residual, tangent, averageStress);
  double volume = 0.0;

  double dNdx[kMaxNodes * D];
  // w C B and, for unsymmetric material tangents, w (C - C^T) B, as V x nd row-major
  // matrices: K's rows are then contiguous fused axpys of their rows, which vectorize.
  double CB[V * kMaxNodes * D];
  double SB[V * kMaxNodes * D];
  MaterialInput in;
  in.temperature = temperature;
  MaterialOutput out;
  for (int q = 0; q < numPoints_; ++q) {
    const double w = gradients(q, x, dNdx);
    double H[D][D] = {};  // displacement gradient
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j)
          H[i][j] += u[a * D + i] * dNdx[a * D + j];
    in.strain.fill(0.0);
    for (int i = 0; i < D; ++i)
      for (int j = i; j < D; ++j)
        in.strain[kVoigt3[i][j]] = i == j ? H[i][i] : H[i][j] + H[j][i];
    evaluateSmallStrainPoint(q, w, material, stateOld, stateNew, in, out, pointStress,
                             averageStress, volume);
    if (residual) {
      double sigma[D][D];
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j)
          sigma[i][j] = w * out.stress[kVoigt3[i][j]];
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < D; ++i) {
          double f = 0.0;
          for (int j = 0; j < D; ++j)
            f += sigma[i][j] * dNdx[a * D + j];
          residual[a * D + i] += f;
        }
    }
    if (tangent) accumulateTangent<D>(out.tangent.data(), w, dNdx, CB, SB, tangent);
  }
  // Only the blocks b >= a were accumulated (plus unsymmetric corrections below the diagonal):
  // mirror the strictly upper blocks.
  if (tangent) addMirroredUpperBlocks<D>(tangent);
  if (averageStress)
    for (int k = 0; k < 6; ++k)
      averageStress[k] /= volume;
}

// Adds w B^T C B at one quadrature point. Only the blocks b >= a of K_ab = B_a^T C B_b are
// added: evaluateIn mirrors them to b < a at the end. When C is unsymmetric, the mirror would
// give B_a^T C^T B_b there instead, so the difference B_a^T (C - C^T) B_b is added now.
template <int D>
void SmallStrainKernel::accumulateTangent(const double* C6, double w, const double* dNdx,
                                          double* CB, double* SB, double* tangent) const {
  constexpr int V = D == 2 ? 3 : 6;
  const int n = numNodes_, nd = D * n;
  double C[V][V];
  for (int p = 0; p < V; ++p)
    for (int r = 0; r < V; ++r) {
      const int rp = D == 3 ? p : kPlaneRows[p], rr = D == 3 ? r : kPlaneRows[r];
      C[p][r] = C6[rp * 6 + rr];
    }
  bool symmetric = true;
  for (int p = 0; p < V; ++p)
    for (int r = 0; r < p; ++r)
      symmetric = symmetric && C[p][r] == C[r][p];
  // (C B)[v][b D + k] = sum_l C[v][voigt(k, l)] dN_b/dx_l: B's columns have 1 to 3 nonzeros.
  for (int b = 0; b < n; ++b) {
    const double* g = &dNdx[b * D];
    for (int k = 0; k < D; ++k)
      for (int v = 0; v < V; ++v) {
        double s = 0.0, t = 0.0;
        for (int l = 0; l < D; ++l) {
          s += C[v][voigt<D>(k, l)] * g[l];
          if (!symmetric) t += (C[v][voigt<D>(k, l)] - C[voigt<D>(k, l)][v]) * g[l];
        }
        CB[v * nd + b * D + k] = w * s;
        if (!symmetric) SB[v * nd + b * D + k] = w * t;
      }
  }
  // Row (a, i) of B^T M is sum_j dN_a/dx_j M[voigt(i, j)]: D fused rows of M.
  for (int a = 0; a < n; ++a) {
    const double* g = &dNdx[a * D];
    for (int i = 0; i < D; ++i) {
      double* row = &tangent[(a * D + i) * nd];
      const double* m0 = &CB[voigt<D>(i, 0) * nd];
      const double* m1 = &CB[voigt<D>(i, 1) * nd];
      if constexpr (D == 2) {
        for (int c = a * D; c < nd; ++c)
          row[c] += g[0] * m0[c] + g[1] * m1[c];
      } else {
        const double* m2 = &CB[voigt<D>(i, 2) * nd];
        for (int c = a * D; c < nd; ++c)
          row[c] += g[0] * m0[c] + g[1] * m1[c] + g[2] * m2[c];
      }
      if (symmetric) continue;
      for (int j = 0; j < D; ++j) {
        const double* s = &SB[voigt<D>(i, j) * nd];
        for (int c = 0; c < a * D; ++c)
          row[c] += g[j] * s[c];
      }
    }
  }
}

template class DimensionTemplatedKernel<SmallStrainKernel>;

}  // namespace contactlab
