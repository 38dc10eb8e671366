#include "core/problem/AxisymmetricTotalLagrangianKernel.hpp"

namespace contactlab {
namespace {

// The components of F (row major 3 x 3) that depend on u: rr, rz, zr, zz, tt.
constexpr int kSlots[5] = {0, 1, 3, 4, 8};

}  // namespace

void AxisymmetricTotalLagrangianKernel::evaluate(const double* x, const double* u,
                                                 const Material& material, const double* stateOld,
                                                 double* stateNew, double* residual,
                                                 double* tangent, double* pointStress,
                                                 double* averageStress,
                                                 const std::optional<double>& temperature) const {
  const int n = numNodes_, nd = 2 * n;
  beginEvaluation(material, stateOld, stateNew, residual, tangent, averageStress);
  double volume = 0.0;
  double dNdX[kMaxNodes * 2];
  double G[5][kMaxNodes * 2];  // dF_slot / du_k
  MaterialInput in;
  in.temperature = temperature;
  MaterialOutput out;
  for (int q = 0; q < numPoints_; ++q) {
    const double w = gradients(q, x, dNdX);  // 2 pi R dA
    const double* N = &N_[q * n];
    double R = 0.0;
    for (int a = 0; a < n; ++a)
      R += N[a] * x[3 * a];
    for (int s = 0; s < 5; ++s)
      for (int k = 0; k < nd; ++k)
        G[s][k] = 0.0;
    for (int a = 0; a < n; ++a) {
      const double dR = dNdX[2 * a], dZ = dNdX[2 * a + 1];
      G[0][2 * a] = dR;        // F_rr
      G[1][2 * a] = dZ;        // F_rz
      G[2][2 * a + 1] = dR;    // F_zr
      G[3][2 * a + 1] = dZ;    // F_zz
      G[4][2 * a] = N[a] / R;  // F_tt = 1 + u_r / R
    }
    in.F = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    for (int s = 0; s < 5; ++s)
      for (int k = 0; k < nd; ++k)
        in.F[kSlots[s]] += G[s][k] * u[k];
    evaluateFiniteStrainPoint(q, w, material, stateOld, stateNew, in, out, pointStress,
                              averageStress, volume);
    addOperatorTerms(5, kSlots, G, nd, w, out.P.data(), out.dPdF.data(), 9, residual, tangent);
  }
  if (averageStress)
    for (int k = 0; k < 6; ++k)
      averageStress[k] /= volume;
}

}  // namespace contactlab
