#include "core/problem/AxisymmetricKernel.hpp"

namespace contactlab {
namespace {

// The Voigt slots the element carries: rr, zz, tt (hoop), rz; the 3D law's xx, yy, zz, xy.
constexpr int kRows[4] = {0, 1, 2, 3};

}  // namespace

void AxisymmetricKernel::evaluate(const double* x, const double* u, const Material& material,
                                  const double* stateOld, double* stateNew, double* residual,
                                  double* tangent, double* pointStress, double* averageStress,
                                  const std::optional<double>& temperature) const {
  const int n = numNodes_, nd = 2 * n;
  beginEvaluation(material, stateOld, stateNew, residual, tangent, averageStress);
  double volume = 0.0;
  double dNdx[kMaxNodes * 2];
  double B[4][kMaxNodes * 2];  // strain = B u, rows rr, zz, tt, rz
  MaterialInput in;
  in.temperature = temperature;
  MaterialOutput out;
  for (int q = 0; q < numPoints_; ++q) {
    const double w = gradients(q, x, dNdx);  // 2 pi r dA
    const double* N = &N_[q * n];
    double r = 0.0;
    for (int a = 0; a < n; ++a)
      r += N[a] * x[3 * a];
    for (int v = 0; v < 4; ++v)
      for (int k = 0; k < nd; ++k)
        B[v][k] = 0.0;
    for (int a = 0; a < n; ++a) {
      const double dr = dNdx[2 * a], dz = dNdx[2 * a + 1];
      B[0][2 * a] = dr;
      B[1][2 * a + 1] = dz;
      B[2][2 * a] = N[a] / r;
      B[3][2 * a] = dz;
      B[3][2 * a + 1] = dr;
    }
    in.strain.fill(0.0);
    for (int v = 0; v < 4; ++v) {
      double e = 0.0;
      for (int k = 0; k < nd; ++k)
        e += B[v][k] * u[k];
      in.strain[kRows[v]] = e;
    }
    evaluateSmallStrainPoint(q, w, material, stateOld, stateNew, in, out, pointStress,
                             averageStress, volume);
    addOperatorTerms(4, kRows, B, nd, w, out.stress.data(), out.tangent.data(), 6, residual,
                     tangent);
  }
  if (averageStress)
    for (int k = 0; k < 6; ++k)
      averageStress[k] /= volume;
}

}  // namespace contactlab
