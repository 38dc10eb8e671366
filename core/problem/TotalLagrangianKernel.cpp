#include "core/problem/TotalLagrangianKernel.hpp"

namespace contactlab {

template <int D>
void TotalLagrangianKernel::evaluateIn(const double* x, const double* u, const Material& material,
                                       const double* stateOld, double* stateNew, double* residual,
                                       double* tangent, double* pointStress, double* averageStress,
                                       const std::optional<double>& temperature) const {
  const int n = numNodes_, nd = D * n;
  beginEvaluation(material, stateOld, stateNew, residual, tangent, averageStress);
  double volume = 0.0;

  double dNdX[kMaxNodes * D];
  // AB[(i D + J) nd + b D + k] = w sum_L dP_iJ/dF_kL dN_b/dX_L: the tangent's rows are then
  // D fused rows of AB, as in the small-strain kernel.
  double AB[D * D * kMaxNodes * D];
  // A material whose dP/dF has the major symmetry dP_iJ/dF_kL = dP_kL/dF_iJ (symmetricTangent)
  // gives a symmetric K: only the blocks b >= a are accumulated (row (a, i) from column a D on),
  // and mirrored at the end, as in the small-strain kernel. Its dP/dF is symmetric up to
  // round-off only, so the material's word decides, not a comparison.
  const bool symmetric = material.symmetricTangent();
  MaterialInput in;
  in.temperature = temperature;
  MaterialOutput out;
  for (int q = 0; q < numPoints_; ++q) {
    const double w = gradients(q, x, dNdX);
    in.F = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < D; ++i)
        for (int J = 0; J < D; ++J)
          in.F[i * 3 + J] += u[a * D + i] * dNdX[a * D + J];
    evaluateFiniteStrainPoint(q, w, material, stateOld, stateNew, in, out, pointStress,
                              averageStress, volume);
    if (residual)
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < D; ++i) {
          double f = 0.0;
          for (int J = 0; J < D; ++J)
            f += out.P[i * 3 + J] * dNdX[a * D + J];
          residual[a * D + i] += w * f;
        }
    if (!tangent) continue;
    for (int i = 0; i < D; ++i)
      for (int J = 0; J < D; ++J) {
        double* row = &AB[(i * D + J) * nd];
        const double* A = &out.dPdF[(i * 3 + J) * 9];
        for (int b = 0; b < n; ++b)
          for (int k = 0; k < D; ++k) {
            double s = 0.0;
            for (int L = 0; L < D; ++L)
              s += A[k * 3 + L] * dNdX[b * D + L];
            row[b * D + k] = w * s;
          }
      }
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < D; ++i) {
        // Row (a, i) is sum_J dN_a/dX_J AB[i D + J]: D fused rows, which vectorize.
        double* row = &tangent[(a * D + i) * nd];
        const double* g = &dNdX[a * D];
        const double* m0 = &AB[(i * D) * nd];
        const double* m1 = &AB[(i * D + 1) * nd];
        const int first = symmetric ? a * D : 0;
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
  if (tangent && symmetric) addMirroredUpperBlocks<D>(tangent);
  if (averageStress)
    for (int k = 0; k < 6; ++k)
      averageStress[k] /= volume;
}

template class DimensionTemplatedKernel<TotalLagrangianKernel>;

}  // namespace contactlab
