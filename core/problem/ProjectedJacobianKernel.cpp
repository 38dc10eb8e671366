#include "core/problem/ProjectedJacobianKernel.hpp"

#include "core/fem/IsoparametricMap.hpp"
#include "core/materials/Tensor3.hpp"
#include "core/problem/ElementUpdateError.hpp"
#include "core/problem/FiniteStrainProducts.hpp"
#include "core/problem/PressureSpace.hpp"
#include "core/problem/ProjectedDilatationKernel.hpp"
#include "core/problem/SlotOperator.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace contactlab {
namespace {

constexpr int kPoints = PressureSpace::kMaxPoints;
constexpr int kDofs = SlotOperator::kMaxDofs;
constexpr int kRows = SlotOperator::kMaxRows;

// What the element's passes keep of each quadrature point.
struct PointData {
  double w = 0;                  // measure
  double X[3] = {};              // reference position
  std::array<double, 9> F{};     // deformation gradient
  std::array<double, 9> Finv{};  // its inverse
  double J = 0;
  double theta = 0;     // Pi(J) at the point
  double alpha = 0;     // (theta / J)^(1/n)
  double tau = 0;       // alpha P_bar : F
  double c[kDofs];      // d ln J / du
  double e[kDofs];      // d ln theta / du
  double delta[kDofs];  // d ln alpha / du = (e - c) / n
  double P[kRows];      // P(F_bar) in the operator's rows
  double A[kRows * kRows];
};

struct ElementData {
  PointData point[kPoints];
  double dNdX[kPoints][81];
};

// det F at point q, checked positive.
double checkedJacobian(const std::array<double, 9>& F, int q) {
  const double J = tensor3::determinant(F);
  if (!(J > 0)) {
    std::ostringstream s;
    s << "det F = " << J << " <= 0: the displacement turns the element inside out";
    throw ElementUpdateError("inverted-element", q, s.str());
  }
  return J;
}

// The projection of J on the pressure space: theta_i = sum_q weight(i, q) J_q and its
// derivative's e_i = sum_q weight(i, q) J_q c_q.
struct Projection {
  double theta[PressureSpace::kMaxSize];
  double e[PressureSpace::kMaxSize][kDofs];

  void set(const PressureSpace& space, const ElementData& data, int nq, int nd) {
    for (int i = 0; i < space.size(); ++i) {
      theta[i] = 0.0;
      std::fill(e[i], e[i] + nd, 0.0);
      for (int q = 0; q < nq; ++q) {
        const double wJ = space.weight(i, q) * data.point[q].J;
        theta[i] += wJ;
        for (int k = 0; k < nd; ++k)
          e[i][k] += wJ * data.point[q].c[k];
      }
    }
  }

  // theta = Pi(J) at point q, e = d ln theta / du and delta = (e - c) / n there.
  void volumeChangeAt(const PressureSpace& space, int q, int nd, double nv, PointData& p) const {
    const int np = space.size();
    p.theta = 0.0;
    for (int i = 0; i < np; ++i)
      p.theta += space.basis(q, i) * theta[i];
    if (!(p.theta > 0))
      throw ElementUpdateError("inverted-element", q,
                               "the element's projected volume change is not positive");
    for (int k = 0; k < nd; ++k) {
      double sum = 0.0;
      for (int i = 0; i < np; ++i)
        sum += space.basis(q, i) * e[i][k];
      p.e[k] = sum / p.theta;
      p.delta[k] = (p.e[k] - p.c[k]) / nv;
    }
  }
};

// rho_i = sum_q w tau psi_i / (n theta): the pressure's moments the tangent's projection terms
// gather per point.
void pressureMoments(const PressureSpace& space, const ElementData& data, int nq, double nv,
                     double* rho) {
  for (int i = 0; i < space.size(); ++i) {
    rho[i] = 0.0;
    for (int q = 0; q < nq; ++q)
      rho[i] +=
          data.point[q].w * data.point[q].tau * space.basis(q, i) / (nv * data.point[q].theta);
  }
}

}  // namespace

ProjectedJacobianKernel::ProjectedJacobianKernel(ElementType type, int pressureDegree,
                                                 bool axisymmetric, int quadratureDegree)
    : PlanarOrRingKernel(
          type, quadratureDegree < 0 ? fullIntegrationDegree(type, axisymmetric) : quadratureDegree,
          axisymmetric),
      pressureDegree_(pressureDegree) {
  PressureSpace::checkKernel("ProjectedJacobianKernel", pressureDegree, numPoints_);
}

// Plane strain and 3D: evaluateRing's three passes below through the total-Lagrangian kernel's
// products (FiniteStrainProducts.hpp), the points' P and dP/dF kept as whole tensors.
template <int D>
void ProjectedJacobianKernel::evaluatePlanar(const double* x, const double* u,
                                             const Material& material, const double* stateOld,
                                             double* stateNew, double* residual, double* tangent,
                                             double* pointStress, double* averageStress,
                                             const std::optional<double>& temperature) const {
  constexpr double nv = D;
  const int n = numNodes_, nq = numPoints_, nd = D * n;
  beginEvaluation(material, stateOld, stateNew, residual, tangent, averageStress);
  double volume = 0.0;
  static thread_local ElementData data;

  double points[3 * kPoints], measures[kPoints];
  for (int q = 0; q < nq; ++q) {
    PointData& p = data.point[q];
    p.w = measures[q] = gradients(q, x, data.dNdX[q]);
    p.F = deformationGradientOf<D>(n, data.dNdX[q], u);
    p.J = checkedJacobian(p.F, q);
    p.Finv = tensor3::inverse(p.F, p.J);
    const auto FinvT = tensor3::transpose(p.Finv);
    std::fill(p.c, p.c + nd, 0.0);
    addGradientTransposeProduct<D>(n, data.dNdX[q], FinvT.data(), 1.0, p.c);
  }
  referencePoints(points);
  PressureSpace space(pressureDegree_, dim_);
  space.setElement(nq, points, measures);
  const int np = space.size();
  static thread_local Projection projection;
  projection.set(space, data, nq, nd);

  MaterialInput in;
  in.temperature = temperature;
  MaterialOutput out;
  for (int q = 0; q < nq; ++q) {
    PointData& p = data.point[q];
    projection.volumeChangeAt(space, q, nd, nv, p);
    p.alpha = std::pow(p.theta / p.J, 1.0 / nv);
    in.F = p.F;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j)
        in.F[i * 3 + j] *= p.alpha;
    evaluateFiniteStrainPoint(q, p.w, material, stateOld, stateNew, in, out, pointStress,
                              averageStress, volume);
    p.tau = 0.0;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j)
        p.tau += p.alpha * out.P[i * 3 + j] * p.F[i * 3 + j];
    std::copy(out.P.begin(), out.P.end(), p.P);
    std::copy(out.dPdF.begin(), out.dPdF.end(), p.A);
    if (!residual) continue;
    addGradientTransposeProduct<D>(n, data.dNdX[q], p.P, p.w * p.alpha, residual);
    for (int k = 0; k < nd; ++k)
      residual[k] += p.w * p.tau * p.delta[k];
  }
  if (averageStress)
    for (int k = 0; k < 6; ++k)
      averageStress[k] /= volume;
  if (!tangent) return;

  const bool symmetric = material.symmetricTangent();
  double rho[PressureSpace::kMaxSize];
  pressureMoments(space, data, nq, nv, rho);
  double AB[D * D * kMaxNodes * D];
  for (int q = 0; q < nq; ++q) {
    const PointData& p = data.point[q];
    const double* dNdX = data.dNdX[q];
    double kappa = 0.0;
    for (int i = 0; i < np; ++i)
      kappa += space.weight(i, q) * rho[i];
    kappa *= p.J;
    // M = w alpha^2 A + (kappa - w tau / n) L, L_iJkL = -(F^-1)_Jk (F^-1)_Li.
    const double a2 = p.alpha * p.alpha, l = kappa - p.w * p.tau / nv;
    double M[81];
    std::array<double, 9> AF = {}, AtF = {};
    double phi = 0.0;
    for (int i = 0; i < D; ++i)
      for (int J = 0; J < D; ++J)
        for (int k = 0; k < D; ++k)
          for (int L = 0; L < D; ++L) {
            const double A = p.A[(i * 3 + J) * 9 + k * 3 + L];
            M[(i * 3 + J) * 9 + k * 3 + L] =
                p.w * a2 * A - l * p.Finv[J * 3 + k] * p.Finv[L * 3 + i];
            AF[i * 3 + J] += A * p.F[k * 3 + L];
            AtF[k * 3 + L] += A * p.F[i * 3 + J];
          }
    for (int i = 0; i < D; ++i)
      for (int J = 0; J < D; ++J)
        phi += p.F[i * 3 + J] * AF[i * 3 + J];
    addGradientTangent<D>(n, dNdX, M, 1.0, AB, tangent, symmetric);
    double yR[kDofs] = {}, yL[kDofs] = {};
    addGradientTransposeProduct<D>(n, dNdX, p.P, p.alpha, yR);
    addGradientTransposeProduct<D>(n, dNdX, AF.data(), a2, yR);
    addGradientTransposeProduct<D>(n, dNdX, p.P, p.alpha, yL);
    addGradientTransposeProduct<D>(n, dNdX, AtF.data(), a2, yL);
    const double half = 0.5 * (p.tau + a2 * phi);
    for (int k = 0; k < nd; ++k) {
      yR[k] += half * p.delta[k];
      yL[k] += half * p.delta[k];
    }
    addOuterProduct(yR, p.delta, p.w, nd, D, tangent, symmetric);
    addOuterProduct(p.delta, yL, p.w, nd, D, tangent, symmetric);
    addOuterProduct(p.c, p.c, kappa, nd, D, tangent, symmetric);
    addOuterProduct(p.e, p.e, -p.w * p.tau / nv, nd, D, tangent, symmetric);
  }
  if (symmetric) addMirroredUpperBlocks<D>(tangent);
}

void ProjectedJacobianKernel::evaluateRing(const double* x, const double* u,
                                           const Material& material, const double* stateOld,
                                           double* stateNew, double* residual, double* tangent,
                                           double* pointStress, double* averageStress,
                                           const std::optional<double>& temperature) const {
  const int n = numNodes_, nq = numPoints_, nd = numDofs();
  beginEvaluation(material, stateOld, stateNew, residual, tangent, averageStress);
  double volume = 0.0;
  static thread_local ElementData data;  // large: kept off the stack
  SlotOperator op;
  auto operatorAt = [&](int q) {
    deformationGradientOperator(dim_, axisymmetric_, n, &N_[q * n], data.dNdX[q],
                                data.point[q].X[0], op);
  };

  // Pass 1: F, J and d ln J / du at each point; theta = Pi(J) and its derivative.
  double points[3 * kPoints], measures[kPoints];
  for (int q = 0; q < nq; ++q) {
    PointData& p = data.point[q];
    p.w = gradients(q, x, data.dNdX[q]);
    interpolatePosition(n, x, &N_[q * n], p.X);
    operatorAt(q);
    p.F = deformationGradient(op, u);
    p.J = checkedJacobian(p.F, q);
    p.Finv = tensor3::inverse(p.F, p.J);
    double g[kRows];
    logJacobianGradient(op, p.Finv, g);
    for (int k = 0; k < nd; ++k)
      p.c[k] = 0.0;
    op.addTransposeProduct(g, 1.0, p.c);
    measures[q] = p.w;
  }
  referencePoints(points);
  const double nv = op.volumetricCount;
  PressureSpace space(pressureDegree_, dim_);
  space.setElement(nq, points, measures);
  const int np = space.size();
  static thread_local Projection projection;
  projection.set(space, data, nq, nd);

  // Pass 2: the material at F_bar; the residual f = sum_q w (alpha B^T P + tau delta).
  MaterialInput in;
  in.temperature = temperature;
  MaterialOutput out;
  for (int q = 0; q < nq; ++q) {
    PointData& p = data.point[q];
    projection.volumeChangeAt(space, q, nd, nv, p);
    operatorAt(q);
    p.alpha = std::pow(p.theta / p.J, 1.0 / nv);
    in.F = p.F;
    for (int r = 0; r < op.rows; ++r)
      in.F[op.slot[r]] = p.alpha * p.F[op.slot[r]];
    evaluateFiniteStrainPoint(q, p.w, material, stateOld, stateNew, in, out, pointStress,
                              averageStress, volume);
    p.tau = 0.0;
    for (int r = 0; r < op.rows; ++r) {
      p.P[r] = out.P[op.slot[r]];
      p.tau += p.alpha * p.P[r] * p.F[op.slot[r]];
    }
    restrictToSlots(op, out.dPdF.data(), 9, p.A);
    if (!residual) continue;
    op.addTransposeProduct(p.P, p.w * p.alpha, residual);
    for (int k = 0; k < nd; ++k)
      residual[k] += p.w * p.tau * p.delta[k];
  }
  if (averageStress)
    for (int k = 0; k < 6; ++k)
      averageStress[k] /= volume;
  if (!tangent) return;

  // Pass 3: K = sum_q w [alpha^2 B^T A B + y_R delta^T + delta y_L^T + (tau + alpha^2 F:A:F)
  // delta delta^T + tau d delta], d delta = (d e - d c) / n, d c = B^T L B (L the Hessian of
  // ln J), d e = (1 / theta) Pi(J (c c^T + B^T L B)) - e e^T; the projection's terms gathered
  // per point through kappa_q = J_q sum_i weight(i, q) rho_i, rho_i = sum_q w tau psi_i / (n
  // theta).
  const bool symmetric = material.symmetricTangent();
  double rho[PressureSpace::kMaxSize];
  pressureMoments(space, data, nq, nv, rho);
  for (int q = 0; q < nq; ++q) {
    const PointData& p = data.point[q];
    operatorAt(q);
    const int rows = op.rows;
    double kappa = 0.0;
    for (int i = 0; i < np; ++i)
      kappa += space.weight(i, q) * rho[i];
    kappa *= p.J;
    double L[kRows * kRows], M[kRows * kRows];
    logJacobianHessian(op, p.Finv, L);
    const double a2 = p.alpha * p.alpha;
    for (int k = 0; k < rows * rows; ++k)
      M[k] = p.w * a2 * p.A[k] + (kappa - p.w * p.tau / nv) * L[k];
    op.addProduct(M, 1.0, tangent, symmetric);
    double AF[kRows] = {}, AtF[kRows] = {}, phi = 0.0;
    for (int r = 0; r < rows; ++r)
      for (int m = 0; m < rows; ++m) {
        AF[r] += p.A[r * rows + m] * p.F[op.slot[m]];
        AtF[r] += p.A[m * rows + r] * p.F[op.slot[m]];
      }
    for (int r = 0; r < rows; ++r)
      phi += p.F[op.slot[r]] * AF[r];
    double yR[kDofs] = {}, yL[kDofs] = {};
    op.addTransposeProduct(p.P, p.alpha, yR);
    op.addTransposeProduct(AF, a2, yR);
    op.addTransposeProduct(p.P, p.alpha, yL);
    op.addTransposeProduct(AtF, a2, yL);
    const double half = 0.5 * (p.tau + a2 * phi);
    for (int k = 0; k < nd; ++k) {
      yR[k] += half * p.delta[k];
      yL[k] += half * p.delta[k];
    }
    addOuterProduct(yR, p.delta, p.w, nd, dim_, tangent, symmetric);
    addOuterProduct(p.delta, yL, p.w, nd, dim_, tangent, symmetric);
    addOuterProduct(p.c, p.c, kappa, nd, dim_, tangent, symmetric);
    addOuterProduct(p.e, p.e, -p.w * p.tau / nv, nd, dim_, tangent, symmetric);
  }
  if (symmetric) mirrorUpperBlocks(nd, dim_, tangent);
}

template class PlanarOrRingKernel<ProjectedJacobianKernel>;

}  // namespace contactlab
