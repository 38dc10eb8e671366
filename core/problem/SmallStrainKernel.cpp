#include "core/problem/SmallStrainKernel.hpp"

#include "core/problem/SmallStrainProducts.hpp"

namespace contactlab {

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
    in.strain.fill(0.0);
    smallStrain<D>(n, dNdx, u, in.strain.data());
    evaluateSmallStrainPoint(q, w, material, stateOld, stateNew, in, out, pointStress,
                             averageStress, volume);
    if (residual) addSmallStrainForce<D>(n, dNdx, out.stress.data(), w, residual);
    if (tangent) addSmallStrainTangent<D>(n, dNdx, out.tangent.data(), w, CB, SB, tangent);
  }
  // Only the blocks b >= a were accumulated (plus unsymmetric corrections below the diagonal):
  // mirror the strictly upper blocks.
  if (tangent) addMirroredUpperBlocks<D>(tangent);
  if (averageStress)
    for (int k = 0; k < 6; ++k)
      averageStress[k] /= volume;
}

template class DimensionTemplatedKernel<SmallStrainKernel>;

}  // namespace contactlab
