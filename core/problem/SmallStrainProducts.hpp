#pragma once
// The small-strain operator B of a 2D (plane strain) or 3D cell at one quadrature point, applied
// through its gradients, written per dimension D at compile time: the products of the full-
// integration kernel (SmallStrainKernel) and of the technologies that modify its strain
// (ProjectedDilatationKernel). n nodes, dNdx the physical gradients (D per node), dof a * D + i.
// Voigt arrays have the 6 components of Material.hpp (xx yy zz xy yz xz, engineering shears);
// in plane strain B's rows are xx yy xy (zz is neither set nor read). Defined here, so that
// each kernel inlines them (the calls are per quadrature point of cells as small as quad4).
// The ring's variants (ringStrain, addRingForce, addRingTangent) add the hoop row.
namespace contactlab {

namespace small_strain_detail {

// Voigt index of the tensor component (i, j): full 3D, and 2D within the plane-strain rows.
constexpr int kVoigt3[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};
constexpr int kVoigt2[2][2] = {{0, 2}, {2, 1}};
constexpr int kPlaneRows[3] = {0, 1, 3};

template <int D>
constexpr int voigt(int i, int j) {
  return D == 3 ? kVoigt3[i][j] : kVoigt2[i][j];
}

}  // namespace small_strain_detail

// strain = B u (the zz, yz, xz slots of a plane-strain point left as they are).
template <int D>
inline void smallStrain(int n, const double* dNdx, const double* u, double* strain) {
  double H[D][D] = {};  // displacement gradient
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j)
        H[i][j] += u[a * D + i] * dNdx[a * D + j];
  for (int i = 0; i < D; ++i)
    for (int j = i; j < D; ++j)
      strain[small_strain_detail::kVoigt3[i][j]] = i == j ? H[i][i] : H[i][j] + H[j][i];
}

// residual += w B^T s for a Voigt stress s.
template <int D>
inline void addSmallStrainForce(int n, const double* dNdx, const double* s, double w,
                                double* residual) {
  double sigma[D][D];
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j)
      sigma[i][j] = w * s[small_strain_detail::kVoigt3[i][j]];
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < D; ++i) {
      double f = 0.0;
      for (int j = 0; j < D; ++j)
        f += sigma[i][j] * dNdx[a * D + j];
      residual[a * D + i] += f;
    }
}

// tangent (nd x nd, nd = D n, row major) += w B^T C B for a 6 x 6 row-major C, in its node
// blocks b >= a only, plus, where C is unsymmetric, w B_a^T (C - C^T) B_b in the blocks b < a:
// addMirroredUpperBlocks then completes it. CB and SB are work arrays of 6 nd doubles.
template <int D>
inline void addSmallStrainTangent(int n, const double* dNdx, const double* C6, double w, double* CB,
                                  double* SB, double* tangent) {
  constexpr int V = D == 2 ? 3 : 6;
  const int nd = D * n;
  double C[V][V];
  for (int p = 0; p < V; ++p)
    for (int r = 0; r < V; ++r) {
      const int rp = D == 3 ? p : small_strain_detail::kPlaneRows[p],
                rr = D == 3 ? r : small_strain_detail::kPlaneRows[r];
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
          s += C[v][small_strain_detail::voigt<D>(k, l)] * g[l];
          if (!symmetric)
            t += (C[v][small_strain_detail::voigt<D>(k, l)] -
                  C[small_strain_detail::voigt<D>(k, l)][v]) *
                 g[l];
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
      const double* m0 = &CB[small_strain_detail::voigt<D>(i, 0) * nd];
      const double* m1 = &CB[small_strain_detail::voigt<D>(i, 1) * nd];
      if constexpr (D == 2) {
        for (int c = a * D; c < nd; ++c)
          row[c] += g[0] * m0[c] + g[1] * m1[c];
      } else {
        const double* m2 = &CB[small_strain_detail::voigt<D>(i, 2) * nd];
        for (int c = a * D; c < nd; ++c)
          row[c] += g[0] * m0[c] + g[1] * m1[c] + g[2] * m2[c];
      }
      if (symmetric) continue;
      for (int j = 0; j < D; ++j) {
        const double* s = &SB[small_strain_detail::voigt<D>(i, j) * nd];
        for (int c = 0; c < a * D; ++c)
          row[c] += g[j] * s[c];
      }
    }
  }
}

// The ring of an axisymmetric cell (x = r, y = z, 2 dofs per node): the plane products plus
// the hoop row eps_tt = sum_a N_a u_a,r / r in Voigt slot zz (2). N: the point's shape values,
// r: its radius. The same conventions as above.
inline void ringStrain(int n, const double* N, const double* dNdx, double r, const double* u,
                       double* strain) {
  smallStrain<2>(n, dNdx, u, strain);
  double hoop = 0.0;
  for (int a = 0; a < n; ++a)
    hoop += N[a] * u[2 * a];
  strain[2] = hoop / r;
}

inline void addRingForce(int n, const double* N, const double* dNdx, double r, const double* s,
                         double w, double* residual) {
  addSmallStrainForce<2>(n, dNdx, s, w, residual);
  const double f = w * s[2] / r;
  for (int a = 0; a < n; ++a)
    residual[2 * a] += f * N[a];
}

// tangent += w B^T C B over the ring's rows, in the node blocks of addSmallStrainTangent (the
// upper ones, and where C is unsymmetric the lower ones' difference). CB, SB: 4 nd doubles each.
inline void addRingTangent(int n, const double* N, const double* dNdx, double r, const double* C6,
                           double w, double* CB, double* SB, double* tangent) {
  constexpr int kSlot[4] = {0, 1, 3, 2};  // rows xx yy xy (those of kVoigt2), then the hoop
  constexpr int kHoop = 3;
  const int nd = 2 * n;
  const double invr = 1.0 / r;
  double C[4][4];
  bool symmetric = true;
  for (int p = 0; p < 4; ++p)
    for (int q = 0; q < 4; ++q)
      C[p][q] = C6[kSlot[p] * 6 + kSlot[q]];
  for (int p = 0; p < 4; ++p)
    for (int q = 0; q < p; ++q)
      symmetric = symmetric && C[p][q] == C[q][p];
  // (C B)[v][b 2 + k] = sum_l C[v][voigt(k, l)] dN_b/dx_l (+ C[v][hoop] N_b / r for k = 0).
  for (int b = 0; b < n; ++b) {
    const double* g = &dNdx[b * 2];
    const double hb = N[b] * invr;
    for (int k = 0; k < 2; ++k)
      for (int v = 0; v < 4; ++v) {
        const int k0 = small_strain_detail::kVoigt2[k][0], k1 = small_strain_detail::kVoigt2[k][1];
        double s = C[v][k0] * g[0] + C[v][k1] * g[1];
        if (k == 0) s += C[v][kHoop] * hb;
        CB[v * nd + b * 2 + k] = w * s;
        if (symmetric) continue;
        double t = (C[v][k0] - C[k0][v]) * g[0] + (C[v][k1] - C[k1][v]) * g[1];
        if (k == 0) t += (C[v][kHoop] - C[kHoop][v]) * hb;
        SB[v * nd + b * 2 + k] = w * t;
      }
  }
  // Row (a, i) of B^T M: dN_a/dx_j M[voigt(i, j)] (+ N_a / r M[hoop] for i = 0).
  for (int a = 0; a < n; ++a) {
    const double* g = &dNdx[a * 2];
    const double ha = N[a] * invr;
    for (int i = 0; i < 2; ++i) {
      double* row = &tangent[(a * 2 + i) * nd];
      const int i0 = small_strain_detail::kVoigt2[i][0], i1 = small_strain_detail::kVoigt2[i][1];
      const double *m0 = &CB[i0 * nd], *m1 = &CB[i1 * nd], *mh = &CB[kHoop * nd];
      if (i == 0)
        for (int c = a * 2; c < nd; ++c)
          row[c] += g[0] * m0[c] + g[1] * m1[c] + ha * mh[c];
      else
        for (int c = a * 2; c < nd; ++c)
          row[c] += g[0] * m0[c] + g[1] * m1[c];
      if (symmetric) continue;
      const double *s0 = &SB[i0 * nd], *s1 = &SB[i1 * nd], *sh = &SB[kHoop * nd];
      for (int c = 0; c < a * 2; ++c)
        row[c] += g[0] * s0[c] + g[1] * s1[c] + (i == 0 ? ha * sh[c] : 0.0);
    }
  }
}

}  // namespace contactlab
