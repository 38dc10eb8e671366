#include "core/problem/FBarKernel.hpp"

#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/ReferenceElement.hpp"
#include "core/materials/Tensor3.hpp"
#include "core/problem/ElementUpdateError.hpp"
#include "core/problem/FiniteStrainProducts.hpp"
#include "core/problem/ProjectedDilatationKernel.hpp"
#include "core/problem/SlotOperator.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace contactlab {
namespace {

// The determinant of F, checked positive (else the iterate turns the cell inside out).
double positiveJacobian(const std::array<double, 9>& F, int point, const char* where) {
  const double J = tensor3::determinant(F);
  if (!(J > 0)) {
    std::ostringstream s;
    s << "det F = " << J << " <= 0 " << where << ": the displacement turns the element inside out";
    throw ElementUpdateError("inverted-element", point, s.str());
  }
  return J;
}

}  // namespace

FBarKernel::FBarKernel(ElementType type, bool axisymmetric, int quadratureDegree)
    : PlanarOrRingKernel(
          type, quadratureDegree < 0 ? fullIntegrationDegree(type, axisymmetric) : quadratureDegree,
          axisymmetric) {
  if (type != ElementType::Quad4 && type != ElementType::Hex8)
    throw std::invalid_argument(std::string("the F-bar kernel takes quad4 or hex8 cells, not ") +
                                info(type).name);
  const ReferenceElement& ref = ReferenceElement::get(type);
  const double centre[3] = {0.0, 0.0, 0.0};
  centreN_.resize(numNodes_);
  centreDNdxi_.resize(numNodes_ * dim_);
  ref.shape(centre, centreN_.data());
  ref.shapeDerivatives(centre, centreDNdxi_.data());
}

// Plane strain and 3D: the terms of evaluateRing below through the total-Lagrangian kernel's
// products (FiniteStrainProducts.hpp); B^T T = sum_J T_iJ dN_a/dX_J over the in-plane slots.
template <int D>
void FBarKernel::evaluatePlanar(const double* x, const double* u, const Material& material,
                                const double* stateOld, double* stateNew, double* residual,
                                double* tangent, double* pointStress, double* averageStress,
                                const std::optional<double>& temperature) const {
  constexpr int ND = kMaxNodes * D;
  constexpr double nv = D;
  const int n = numNodes_, nd = D * n;
  beginEvaluation(material, stateOld, stateNew, residual, tangent, averageStress);
  double volume = 0.0;

  double dNdX[ND];
  physicalGradients(D, n, x, centreDNdxi_.data(), dNdX);
  const auto F0 = deformationGradientOf<D>(n, dNdX, u);
  const double J0 = positiveJacobian(F0, -1, "at the element's centre");
  double c0[ND] = {};
  addGradientTransposeProduct<D>(n, dNdX, tensor3::transpose(tensor3::inverse(F0, J0)).data(), 1.0,
                                 c0);

  double centreColumn[ND] = {}, AB[D * D * ND];
  MaterialInput in;
  in.temperature = temperature;
  MaterialOutput out;
  for (int q = 0; q < numPoints_; ++q) {
    const double w = gradients(q, x, dNdX);
    const auto F = deformationGradientOf<D>(n, dNdX, u);
    const double J = positiveJacobian(F, q, "at a quadrature point");
    const double alpha = std::pow(J0 / J, 1.0 / nv);
    in.F = F;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j)
        in.F[i * 3 + j] *= alpha;
    evaluateFiniteStrainPoint(q, w, material, stateOld, stateNew, in, out, pointStress,
                              averageStress, volume);
    const double g = std::pow(alpha, 1.0 - nv);
    if (residual) addGradientTransposeProduct<D>(n, dNdX, out.P.data(), w * g, residual);
    if (!tangent) continue;
    addGradientTangent<D>(n, dNdX, out.dPdF.data(), w * g * alpha, AB, tangent, false);
    std::array<double, 9> AF = {};
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j)
        for (int k = 0; k < D; ++k)
          for (int l = 0; l < D; ++l)
            AF[i * 3 + j] += out.dPdF[(i * 3 + j) * 9 + k * 3 + l] * F[k * 3 + l];
    double v[ND] = {}, c[ND] = {};
    addGradientTransposeProduct<D>(n, dNdX, out.P.data(), w * (1.0 - nv) * std::pow(alpha, -nv), v);
    addGradientTransposeProduct<D>(n, dNdX, AF.data(), w * g, v);
    addGradientTransposeProduct<D>(n, dNdX, tensor3::transpose(tensor3::inverse(F, J)).data(), 1.0,
                                   c);
    addOuterProduct(v, c, -alpha / nv, nd, D, tangent, false);
    for (int k = 0; k < nd; ++k)
      centreColumn[k] += alpha / nv * v[k];
  }
  if (tangent) addOuterProduct(centreColumn, c0, 1.0, nd, D, tangent, false);
  if (averageStress)
    for (int k = 0; k < 6; ++k)
      averageStress[k] /= volume;
}

void FBarKernel::evaluateRing(const double* x, const double* u, const Material& material,
                              const double* stateOld, double* stateNew, double* residual,
                              double* tangent, double* pointStress, double* averageStress,
                              const std::optional<double>& temperature) const {
  constexpr int D = SlotOperator::kMaxDofs, R = SlotOperator::kMaxRows;
  const int n = numNodes_, nd = numDofs();
  beginEvaluation(material, stateOld, stateNew, residual, tangent, averageStress);
  double volume = 0.0;

  // The centre: J0 and c0 = d ln J0 / du.
  SlotOperator op;
  double dNdX[kMaxNodes * 3];
  physicalGradients(dim_, n, x, centreDNdxi_.data(), dNdX);
  double centre[3];
  interpolatePosition(n, x, centreN_.data(), centre);
  deformationGradientOperator(dim_, axisymmetric_, n, centreN_.data(), dNdX, centre[0], op);
  const auto F0 = deformationGradient(op, u);
  const double J0 = positiveJacobian(F0, -1, "at the element's centre");
  double g0[R], c0[D] = {};
  logJacobianGradient(op, tensor3::inverse(F0, J0), g0);
  op.addTransposeProduct(g0, 1.0, c0);
  const double nv = op.volumetricCount;

  double centreColumn[D] = {};  // sum_q (alpha_q / n) v_q, which multiplies c0^T
  MaterialInput in;
  in.temperature = temperature;
  MaterialOutput out;
  for (int q = 0; q < numPoints_; ++q) {
    const double w = gradients(q, x, dNdX);
    const double* N = &N_[q * n];
    double point[3];
    interpolatePosition(n, x, N, point);
    deformationGradientOperator(dim_, axisymmetric_, n, N, dNdX, point[0], op);
    const auto F = deformationGradient(op, u);
    const double J = positiveJacobian(F, q, "at a quadrature point");
    const double alpha = std::pow(J0 / J, 1.0 / nv);
    in.F = F;
    for (int r = 0; r < op.rows; ++r)
      in.F[op.slot[r]] = alpha * F[op.slot[r]];
    evaluateFiniteStrainPoint(q, w, material, stateOld, stateNew, in, out, pointStress,
                              averageStress, volume);
    const double g = std::pow(alpha, 1.0 - nv);  // J / J0 alpha: Cauchy's virtual work
    double Pbar[R];
    for (int r = 0; r < op.rows; ++r)
      Pbar[r] = out.P[op.slot[r]];
    if (residual) op.addTransposeProduct(Pbar, w * g, residual);
    if (!tangent) continue;
    // K = int g alpha B^T A B + v d^T, v = (1 - n) alpha^-n B^T P + g B^T A F,
    // d = d alpha / du = (alpha / n) (c0 - c), c = d ln J / du.
    double A[R * R], AF[R] = {};
    restrictToSlots(op, out.dPdF.data(), 9, A);
    op.addProduct(A, w * g * alpha, tangent, false);
    for (int r = 0; r < op.rows; ++r)
      for (int m = 0; m < op.rows; ++m)
        AF[r] += A[r * op.rows + m] * F[op.slot[m]];
    double v[D] = {}, c[D] = {}, gJ[R];
    op.addTransposeProduct(Pbar, w * (1.0 - nv) * std::pow(alpha, -nv), v);
    op.addTransposeProduct(AF, w * g, v);
    logJacobianGradient(op, tensor3::inverse(F, J), gJ);
    op.addTransposeProduct(gJ, 1.0, c);
    addOuterProduct(v, c, -alpha / nv, nd, dim_, tangent, false);
    for (int k = 0; k < nd; ++k)
      centreColumn[k] += alpha / nv * v[k];
  }
  if (tangent) addOuterProduct(centreColumn, c0, 1.0, nd, dim_, tangent, false);
  if (averageStress)
    for (int k = 0; k < 6; ++k)
      averageStress[k] /= volume;
}

template class PlanarOrRingKernel<FBarKernel>;

}  // namespace contactlab
