#include "core/problem/ProjectedDilatationKernel.hpp"

#include "core/fem/IsoparametricMap.hpp"
#include "core/problem/AxisymmetricKernel.hpp"
#include "core/problem/PressureSpace.hpp"
#include "core/problem/SlotOperator.hpp"
#include "core/problem/SmallStrainProducts.hpp"

#include <array>
#include <stdexcept>

namespace contactlab {

namespace {

// Sets the first `rows` rows of m to zero over `columns` (not the whole array: it is large).
template <int Columns>
void clearRows(double (*m)[Columns], int rows, int columns) {
  for (int i = 0; i < rows; ++i)
    for (int k = 0; k < columns; ++k)
      m[i][k] = 0.0;
}

// The Voigt slots of a plane-strain (xx yy xy) and a 3D cell.
template <int D>
constexpr int kSlots[D == 2 ? 3 : 6] = {};
template <>
constexpr int kSlots<2>[3] = {0, 1, 3};
template <>
constexpr int kSlots<3>[6] = {0, 1, 2, 3, 4, 5};

// K += sum_i (g_i beta_i^T + beta_i gT_i^T) over whole blocks, g_i = h_i / n + sum_j S_ij
// beta_j / (2 n^2) (gT_i with hT_i, or g_i when symmetric): the cross terms B^T P C m b_bar^T / n
// (and their transposes) and the volumetric one b_bar (m^T C m) b_bar^T / n^2 with b_bar =
// sum_i psi_i beta_i.
template <int Columns>
void addDilatationTerms(int np, int nd, int dim, const double (*beta)[Columns],
                        const double (*h)[Columns], const double (*hT)[Columns],
                        const double (*S)[PressureSpace::kMaxSize], double invn, bool symmetric,
                        double* tangent) {
  for (int i = 0; i < np; ++i) {
    double g[Columns], gT[Columns];
    for (int k = 0; k < nd; ++k) {
      double s = 0.0;
      for (int j = 0; j < np; ++j)
        s += S[i][j] * beta[j][k];
      g[k] = invn * h[i][k] + 0.5 * invn * invn * s;
      gT[k] = symmetric ? g[k] : invn * hT[i][k] + 0.5 * invn * invn * s;
    }
    addOuterProduct(g, beta[i], 1.0, nd, dim, tangent, false);
    addOuterProduct(beta[i], gT, 1.0, nd, dim, tangent, false);
  }
}

}  // namespace

int fullIntegrationDegree(ElementType type, bool axisymmetric) {
  return axisymmetric ? AxisymmetricKernel::defaultQuadratureDegree(type)
                      : stiffnessQuadratureDegree(type);
}

ProjectedDilatationKernel::ProjectedDilatationKernel(ElementType type, int pressureDegree,
                                                     bool axisymmetric, int quadratureDegree)
    : PlanarOrRingKernel(
          type, quadratureDegree < 0 ? fullIntegrationDegree(type, axisymmetric) : quadratureDegree,
          axisymmetric),
      pressureDegree_(pressureDegree) {
  PressureSpace::checkKernel("ProjectedDilatationKernel", pressureDegree, numPoints_);
}

// The plane-strain and 3D cells: B^T C' B through the full-integration kernel's products with
// the projected material matrix C' = P C P (P = I - m m^T / n on the Voigt slots), whose
// sparsity is B's, plus the rank-np terms of the projected dilatation.
template <int D>
void ProjectedDilatationKernel::evaluatePlanar(const double* x, const double* u,
                                               const Material& material, const double* stateOld,
                                               double* stateNew, double* residual, double* tangent,
                                               double* pointStress, double* averageStress,
                                               const std::optional<double>& temperature) const {
  constexpr int P = PressureSpace::kMaxPoints, S = PressureSpace::kMaxSize;
  constexpr int ND = kMaxNodes * D;
  constexpr double invn = 1.0 / D;  // the volumetric slots are xx yy (zz): Voigt 0 .. D - 1
  const int n = numNodes_, nq = numPoints_, nd = D * n;
  beginEvaluation(material, stateOld, stateNew, residual, tangent, averageStress);
  double volume = 0.0;

  double dNdx[P][ND], w[P], xi[3 * P];
  for (int q = 0; q < nq; ++q)
    w[q] = gradients(q, x, dNdx[q]);
  if (pressureDegree_ > 0) referencePoints(xi);
  PressureSpace space(pressureDegree_, dim_);
  space.setElement(nq, xi, w);
  const int np = space.size();

  // beta_i = sum_q weight(i, q) b_q, b_q = m^T B_q: the gradients themselves.
  double beta[S][ND], thetaCoefficient[S] = {};
  for (int i = 0; i < np; ++i) {
    for (int k = 0; k < nd; ++k) {
      double b = 0.0;
      for (int q = 0; q < nq; ++q)
        b += space.weight(i, q) * dNdx[q][k];
      beta[i][k] = b;
      thetaCoefficient[i] += b * u[k];
    }
  }

  bool symmetric = true;
  double pressureMoment[S] = {};
  double h[S][ND], hT[S][ND];  // hT: set once a point's C is unsymmetric
  for (int i = 0; i < np; ++i)
    for (int k = 0; k < nd; ++k)
      h[i][k] = 0.0;
  double volumetricStiffness[S][S] = {};
  double CB[6 * ND], SB[6 * ND];
  MaterialInput in;
  in.temperature = temperature;
  MaterialOutput out;
  for (int q = 0; q < nq; ++q) {
    in.strain.fill(0.0);
    smallStrain<D>(n, dNdx[q], u, in.strain.data());
    double trace = 0.0, theta = 0.0;
    for (int r = 0; r < D; ++r)
      trace += in.strain[r];
    for (int i = 0; i < np; ++i)
      theta += space.basis(q, i) * thetaCoefficient[i];
    for (int r = 0; r < D; ++r)
      in.strain[r] += invn * (theta - trace);
    evaluateSmallStrainPoint(q, w[q], material, stateOld, stateNew, in, out, pointStress,
                             averageStress, volume);
    if (residual) {
      std::array<double, 6> sigma = out.stress;
      double traceSigma = 0.0;
      for (int r = 0; r < D; ++r)
        traceSigma += sigma[r];
      for (int r = 0; r < D; ++r)
        sigma[r] -= invn * traceSigma;  // P sigma
      addSmallStrainForce<D>(n, dNdx[q], sigma.data(), w[q], residual);
      for (int i = 0; i < np; ++i)
        pressureMoment[i] += w[q] * space.basis(q, i) * traceSigma;
    }
    if (!tangent) continue;
    // C' = P C P on the element's Voigt slots (the volumetric ones first: xx yy (zz)).
    const double* C = out.tangent.data();
    double Cm[6] = {}, mC[6] = {}, mCm = 0.0;
    for (int r : kSlots<D>)
      for (int m = 0; m < D; ++m) {
        Cm[r] += C[r * 6 + m];
        mC[r] += C[m * 6 + r];
      }
    for (int r = 0; r < D; ++r)
      mCm += Cm[r];
    const bool symmetricSoFar = symmetric;
    double Cp[36], PCm[6] = {}, PCTm[6] = {};
    for (int r : kSlots<D>) {
      const double mr = r < D ? invn : 0.0;
      PCm[r] = Cm[r] - mr * mCm;  // P C m, and P C^T m: the cross terms' columns
      PCTm[r] = mC[r] - mr * mCm;
      for (int m : kSlots<D>) {
        const double mm = m < D ? invn : 0.0;
        Cp[r * 6 + m] = C[r * 6 + m] - mr * mC[m] - Cm[r] * mm + mr * mm * mCm;
        symmetric = symmetric && C[r * 6 + m] == C[m * 6 + r];
      }
    }
    addSmallStrainTangent<D>(n, dNdx[q], Cp, w[q], CB, SB, tangent);
    // h_i += w psi_i B^T P C m, and hT_i with C^T, accumulated from the first unsymmetric point
    // on (h's sum until then).
    if (symmetricSoFar && !symmetric)
      for (int i = 0; i < np; ++i)
        for (int k = 0; k < nd; ++k)
          hT[i][k] = h[i][k];
    for (int i = 0; i < np; ++i) {
      const double psi = space.basis(q, i);
      addSmallStrainForce<D>(n, dNdx[q], PCm, w[q] * psi, h[i]);
      if (!symmetric) addSmallStrainForce<D>(n, dNdx[q], PCTm, w[q] * psi, hT[i]);
      for (int j = 0; j < np; ++j)
        volumetricStiffness[i][j] += w[q] * psi * space.basis(q, j) * mCm;
    }
  }
  if (residual)
    for (int i = 0; i < np; ++i)
      for (int k = 0; k < nd; ++k)
        residual[k] += invn * pressureMoment[i] * beta[i][k];
  if (tangent) {
    addMirroredUpperBlocks<D>(tangent);
    addDilatationTerms(np, nd, D, beta, h, hT, volumetricStiffness, invn, symmetric, tangent);
  }
  if (averageStress)
    for (int k = 0; k < 6; ++k)
      averageStress[k] /= volume;
}

void ProjectedDilatationKernel::evaluateRing(const double* x, const double* u,
                                             const Material& material, const double* stateOld,
                                             double* stateNew, double* residual, double* tangent,
                                             double* pointStress, double* averageStress,
                                             const std::optional<double>& temperature) const {
  constexpr int P = PressureSpace::kMaxPoints, S = PressureSpace::kMaxSize;
  constexpr int D = SlotOperator::kMaxDofs, R = SlotOperator::kMaxRows;
  const int n = numNodes_, nq = numPoints_, nd = numDofs();
  beginEvaluation(material, stateOld, stateNew, residual, tangent, averageStress);
  double volume = 0.0;

  // The points' gradients, measures and positions; the pressure space over them.
  double dNdx[P][kMaxNodes * 3], w[P], points[3 * P], xi[3 * P];
  for (int q = 0; q < nq; ++q) {
    w[q] = gradients(q, x, dNdx[q]);
    interpolatePosition(n, x, &N_[q * n], &points[3 * q]);
  }
  referencePoints(xi);
  PressureSpace space(pressureDegree_, dim_);
  space.setElement(nq, xi, w);
  const int np = space.size();

  // theta_bar = sum_i psi_i beta_i . u, beta_i = sum_q weight(i, q) b_q, b_q = m^T B_q.
  SlotOperator op;
  double beta[S][D];
  clearRows(beta, np, nd);
  for (int q = 0; q < nq; ++q) {
    smallStrainOperator(dim_, axisymmetric_, n, &N_[q * n], dNdx[q], points[3 * q], op);
    for (int k = 0; k < nd; ++k) {
      double b = 0.0;
      for (int r = 0; r < op.rows; ++r)
        if (op.volumetric[r]) b += op.B[r][k];
      for (int i = 0; i < np; ++i)
        beta[i][k] += space.weight(i, q) * b;
    }
  }
  double thetaCoefficient[S] = {};
  for (int i = 0; i < np; ++i)
    for (int k = 0; k < nd; ++k)
      thetaCoefficient[i] += beta[i][k] * u[k];

  // Only the upper node blocks are accumulated while every point's C is symmetric (mirrored at
  // the end); an unsymmetric C at a point mirrors what was accumulated and goes on in full.
  bool symmetric = true;
  double pressureMoment[S] = {};  // sum_q w psi_i tr sigma
  double h[S][D], hT[S][D];       // sum_q w psi_i B^T P C m (and with C^T)
  clearRows(h, np, nd);
  clearRows(hT, np, nd);
  double volumetricStiffness[S][S] = {};  // sum_q w psi_i psi_j m^T C m
  MaterialInput in;
  in.temperature = temperature;
  MaterialOutput out;
  for (int q = 0; q < nq; ++q) {
    smallStrainOperator(dim_, axisymmetric_, n, &N_[q * n], dNdx[q], points[3 * q], op);
    const int rows = op.rows;
    const double invn = 1.0 / op.volumetricCount;
    double e[R];
    op.apply(u, e);
    double trace = 0.0, theta = 0.0;
    for (int r = 0; r < rows; ++r)
      if (op.volumetric[r]) trace += e[r];
    for (int i = 0; i < np; ++i)
      theta += space.basis(q, i) * thetaCoefficient[i];
    in.strain.fill(0.0);
    for (int r = 0; r < rows; ++r)
      in.strain[op.slot[r]] = e[r] + (op.volumetric[r] ? invn * (theta - trace) : 0.0);
    evaluateSmallStrainPoint(q, w[q], material, stateOld, stateNew, in, out, pointStress,
                             averageStress, volume);
    if (residual) {
      double sigma[R], traceSigma = 0.0;
      for (int r = 0; r < rows; ++r) {
        sigma[r] = out.stress[op.slot[r]];
        if (op.volumetric[r]) traceSigma += sigma[r];
      }
      for (int r = 0; r < rows; ++r)
        if (op.volumetric[r]) sigma[r] -= invn * traceSigma;  // P sigma
      op.addTransposeProduct(sigma, w[q], residual);
      for (int i = 0; i < np; ++i)
        pressureMoment[i] += w[q] * space.basis(q, i) * traceSigma;
    }
    if (!tangent) continue;
    double C[R * R], Cm[R] = {}, mC[R] = {}, mCm = 0.0;
    restrictToSlots(op, out.tangent.data(), 6, C);
    for (int r = 0; r < rows && symmetric; ++r)
      for (int m = 0; m < r; ++m)
        if (C[r * rows + m] != C[m * rows + r]) {
          mirrorUpperBlocks(nd, dim_, tangent);
          symmetric = false;
          break;
        }
    for (int r = 0; r < rows; ++r)
      for (int m = 0; m < rows; ++m) {
        if (op.volumetric[m]) Cm[r] += C[r * rows + m];
        if (op.volumetric[r]) mC[m] += C[r * rows + m];
      }
    for (int r = 0; r < rows; ++r)
      if (op.volumetric[r]) mCm += Cm[r];
    // C' = P C P, P = I - m m^T / n.
    double Cp[R * R];
    for (int r = 0; r < rows; ++r)
      for (int m = 0; m < rows; ++m) {
        const double mr = op.volumetric[r] ? 1.0 : 0.0, mm = op.volumetric[m] ? 1.0 : 0.0;
        Cp[r * rows + m] =
            C[r * rows + m] - invn * (mr * mC[m] + Cm[r] * mm) + invn * invn * mr * mm * mCm;
      }
    op.addProduct(Cp, w[q], tangent, symmetric);
    double PCm[R], PCTm[R];
    for (int r = 0; r < rows; ++r) {
      PCm[r] = Cm[r] - (op.volumetric[r] ? invn * mCm : 0.0);
      PCTm[r] = mC[r] - (op.volumetric[r] ? invn * mCm : 0.0);
    }
    double hq[D] = {}, hTq[D] = {};
    op.addTransposeProduct(PCm, w[q], hq);
    op.addTransposeProduct(PCTm, w[q], hTq);
    for (int i = 0; i < np; ++i) {
      const double psi = space.basis(q, i);
      for (int k = 0; k < nd; ++k) {
        h[i][k] += psi * hq[k];
        hT[i][k] += psi * hTq[k];
      }
      for (int j = 0; j < np; ++j)
        volumetricStiffness[i][j] += w[q] * psi * space.basis(q, j) * mCm;
    }
  }
  const double invn = 1.0 / op.volumetricCount;
  if (residual)
    for (int i = 0; i < np; ++i)
      for (int k = 0; k < nd; ++k)
        residual[k] += invn * pressureMoment[i] * beta[i][k];
  if (tangent) {
    if (symmetric) mirrorUpperBlocks(nd, dim_, tangent);
    addDilatationTerms(np, nd, dim_, beta, h, hT, volumetricStiffness, invn, symmetric, tangent);
  }
  if (averageStress)
    for (int k = 0; k < 6; ++k)
      averageStress[k] /= volume;
}

template class PlanarOrRingKernel<ProjectedDilatationKernel>;

}  // namespace contactlab
