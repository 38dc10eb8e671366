#include "core/problem/AxisymmetricKernel.hpp"

#include "core/problem/SmallStrainProducts.hpp"

namespace contactlab {

// The ring's rows rr, zz, tt (hoop), rz in the 3D law's Voigt slots xx, yy, zz, xy, through the
// plane-strain products plus the hoop row (SmallStrainProducts.hpp).
void AxisymmetricKernel::evaluate(const double* x, const double* u, const Material& material,
                                  const double* stateOld, double* stateNew, double* residual,
                                  double* tangent, double* pointStress, double* averageStress,
                                  const std::optional<double>& temperature) const {
  const int n = numNodes_;
  beginEvaluation(material, stateOld, stateNew, residual, tangent, averageStress);
  double volume = 0.0;
  double dNdx[kMaxNodes * 2];
  double CB[4 * kMaxNodes * 2], SB[4 * kMaxNodes * 2];
  MaterialInput in;
  in.temperature = temperature;
  MaterialOutput out;
  for (int q = 0; q < numPoints_; ++q) {
    const double w = gradients(q, x, dNdx);  // 2 pi r dA
    const double* N = &N_[q * n];
    double r = 0.0;
    for (int a = 0; a < n; ++a)
      r += N[a] * x[3 * a];
    in.strain.fill(0.0);
    ringStrain(n, N, dNdx, r, u, in.strain.data());
    evaluateSmallStrainPoint(q, w, material, stateOld, stateNew, in, out, pointStress,
                             averageStress, volume);
    if (residual) addRingForce(n, N, dNdx, r, out.stress.data(), w, residual);
    if (tangent) addRingTangent(n, N, dNdx, r, out.tangent.data(), w, CB, SB, tangent);
  }
  if (tangent) addMirroredUpperBlocks<2>(tangent);
  if (averageStress)
    for (int k = 0; k < 6; ++k)
      averageStress[k] /= volume;
}

}  // namespace contactlab
