#include "core/problem/TotalLagrangianKernel.hpp"

#include "core/problem/FiniteStrainProducts.hpp"

namespace contactlab {

template <int D>
void TotalLagrangianKernel::evaluateIn(const double* x, const double* u, const Material& material,
                                       const double* stateOld, double* stateNew, double* residual,
                                       double* tangent, double* pointStress, double* averageStress,
                                       const std::optional<double>& temperature) const {
  const int n = numNodes_;
  beginEvaluation(material, stateOld, stateNew, residual, tangent, averageStress);
  double volume = 0.0;

  double dNdX[kMaxNodes * D];
  double AB[D * D * kMaxNodes * D];
  // A material whose dP/dF has the major symmetry dP_iJ/dF_kL = dP_kL/dF_iJ (symmetricTangent)
  // gives a symmetric K: only the blocks b >= a are accumulated, and mirrored at the end, as in
  // the small-strain kernel. Its dP/dF is symmetric up to round-off only, so the material's
  // word decides, not a comparison.
  const bool symmetric = material.symmetricTangent();
  MaterialInput in;
  in.temperature = temperature;
  MaterialOutput out;
  for (int q = 0; q < numPoints_; ++q) {
    const double w = gradients(q, x, dNdX);
    in.F = deformationGradientOf<D>(n, dNdX, u);
    evaluateFiniteStrainPoint(q, w, material, stateOld, stateNew, in, out, pointStress,
                              averageStress, volume);
    if (residual) addGradientTransposeProduct<D>(n, dNdX, out.P.data(), w, residual);
    if (tangent) addGradientTangent<D>(n, dNdX, out.dPdF.data(), w, AB, tangent, symmetric);
  }
  if (tangent && symmetric) addMirroredUpperBlocks<D>(tangent);
  if (averageStress)
    for (int k = 0; k < 6; ++k)
      averageStress[k] /= volume;
}

template class DimensionTemplatedKernel<TotalLagrangianKernel>;

}  // namespace contactlab
