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

// A cell's small-strain operator at one quadrature point, for evaluateCell: the products (with
// B's Voigt slots, the volumetric ones first, 0 .. kVolumetric - 1), and the divergence row
// m^T B. Plane strain and 3D: D dofs per node; the ring: 2, and its hoop row.
template <int D>
struct PlanarSlots;
template <>
struct PlanarSlots<2> {
  static constexpr int value[3] = {0, 1, 3};
};
template <>
struct PlanarSlots<3> {
  static constexpr int value[6] = {0, 1, 2, 3, 4, 5};
};

template <int D>
struct PlanarCell {
  static constexpr int kNodeDofs = D, kVolumetric = D, kRows = D == 2 ? 3 : 6;
  static constexpr const auto& kSlots = PlanarSlots<D>::value;
  int n;
  const double* dNdx;
  void strain(const double* u, double* e) const { smallStrain<D>(n, dNdx, u, e); }
  void addForce(const double* s, double w, double* r) const {
    addSmallStrainForce<D>(n, dNdx, s, w, r);
  }
  void addTangent(const double* C, double w, double* CB, double* SB, double* K) const {
    addSmallStrainTangent<D>(n, dNdx, C, w, CB, SB, K);
  }
  double divergence(int k) const { return dNdx[k]; }
};

struct RingCell {
  static constexpr int kNodeDofs = 2, kVolumetric = 3, kRows = 4;
  static constexpr int kSlots[kRows] = {0, 1, 2, 3};
  int n;
  const double* dNdx;
  const double* N;
  double r;
  void strain(const double* u, double* e) const { ringStrain(n, N, dNdx, r, u, e); }
  void addForce(const double* s, double w, double* res) const {
    addRingForce(n, N, dNdx, r, s, w, res);
  }
  void addTangent(const double* C, double w, double* CB, double* SB, double* K) const {
    addRingTangent(n, N, dNdx, r, C, w, CB, SB, K);
  }
  double divergence(int k) const { return dNdx[k] + (k % 2 == 0 ? N[k / 2] / r : 0.0); }
};

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

// B^T C' B through the full-integration kernel's products with the projected material matrix
// C' = P C P (P = I - m m^T / n on the Voigt slots), whose sparsity is B's, plus the rank-np
// terms of the projected dilatation. Cell: PlanarCell<D> or RingCell; cells(q, dNdx) builds
// quadrature point q's.
template <class Cell, class Cells>
void ProjectedDilatationKernel::evaluateCell(const Cells& cells, const double* x, const double* u,
                                             const Material& material, const double* stateOld,
                                             double* stateNew, double* residual, double* tangent,
                                             double* pointStress, double* averageStress,
                                             const std::optional<double>& temperature) const {
  constexpr int P = PressureSpace::kMaxPoints, S = PressureSpace::kMaxSize;
  constexpr int D = Cell::kNodeDofs, ND = kMaxNodes * D, V = Cell::kVolumetric;
  constexpr double invn = 1.0 / V;  // the volumetric slots: Voigt 0 .. V - 1
  const int nq = numPoints_, nd = D * numNodes_;
  beginEvaluation(material, stateOld, stateNew, residual, tangent, averageStress);
  double volume = 0.0;

  double dNdx[P][ND], w[P], xi[3 * P];
  for (int q = 0; q < nq; ++q)
    w[q] = gradients(q, x, dNdx[q]);
  if (pressureDegree_ > 0) referencePoints(xi);
  PressureSpace space(pressureDegree_, dim_);
  space.setElement(nq, xi, w);
  const int np = space.size();

  // beta_i = sum_q weight(i, q) b_q, b_q = m^T B_q.
  double beta[S][ND], thetaCoefficient[S] = {};
  for (int i = 0; i < np; ++i)
    for (int k = 0; k < nd; ++k)
      beta[i][k] = 0.0;
  for (int q = 0; q < nq; ++q) {
    const Cell cell = cells(q, dNdx[q]);
    for (int k = 0; k < nd; ++k) {
      const double b = cell.divergence(k);
      for (int i = 0; i < np; ++i)
        beta[i][k] += space.weight(i, q) * b;
    }
  }
  for (int i = 0; i < np; ++i)
    for (int k = 0; k < nd; ++k)
      thetaCoefficient[i] += beta[i][k] * u[k];

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
    const Cell cell = cells(q, dNdx[q]);
    in.strain.fill(0.0);
    cell.strain(u, in.strain.data());
    double trace = 0.0, theta = 0.0;
    for (int r = 0; r < V; ++r)
      trace += in.strain[r];
    for (int i = 0; i < np; ++i)
      theta += space.basis(q, i) * thetaCoefficient[i];
    for (int r = 0; r < V; ++r)
      in.strain[r] += invn * (theta - trace);
    evaluateSmallStrainPoint(q, w[q], material, stateOld, stateNew, in, out, pointStress,
                             averageStress, volume);
    if (residual) {
      std::array<double, 6> sigma = out.stress;
      double traceSigma = 0.0;
      for (int r = 0; r < V; ++r)
        traceSigma += sigma[r];
      for (int r = 0; r < V; ++r)
        sigma[r] -= invn * traceSigma;  // P sigma
      cell.addForce(sigma.data(), w[q], residual);
      for (int i = 0; i < np; ++i)
        pressureMoment[i] += w[q] * space.basis(q, i) * traceSigma;
    }
    if (!tangent) continue;
    // C' = P C P on the cell's Voigt slots (the volumetric ones first).
    const double* C = out.tangent.data();
    double Cm[6] = {}, mC[6] = {}, mCm = 0.0;
    for (int r : Cell::kSlots)
      for (int m = 0; m < V; ++m) {
        Cm[r] += C[r * 6 + m];
        mC[r] += C[m * 6 + r];
      }
    for (int r = 0; r < V; ++r)
      mCm += Cm[r];
    const bool symmetricSoFar = symmetric;
    double Cp[36], PCm[6] = {}, PCTm[6] = {};
    for (int r : Cell::kSlots) {
      const double mr = r < V ? invn : 0.0;
      PCm[r] = Cm[r] - mr * mCm;  // P C m, and P C^T m: the cross terms' columns
      PCTm[r] = mC[r] - mr * mCm;
      for (int m : Cell::kSlots) {
        const double mm = m < V ? invn : 0.0;
        Cp[r * 6 + m] = C[r * 6 + m] - mr * mC[m] - Cm[r] * mm + mr * mm * mCm;
        symmetric = symmetric && C[r * 6 + m] == C[m * 6 + r];
      }
    }
    cell.addTangent(Cp, w[q], CB, SB, tangent);
    // h_i += w psi_i B^T P C m, and hT_i with C^T, accumulated from the first unsymmetric point
    // on (h's sum until then).
    if (symmetricSoFar && !symmetric)
      for (int i = 0; i < np; ++i)
        for (int k = 0; k < nd; ++k)
          hT[i][k] = h[i][k];
    for (int i = 0; i < np; ++i) {
      const double psi = space.basis(q, i);
      cell.addForce(PCm, w[q] * psi, h[i]);
      if (!symmetric) cell.addForce(PCTm, w[q] * psi, hT[i]);
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

template <int D>
void ProjectedDilatationKernel::evaluatePlanar(const double* x, const double* u,
                                               const Material& material, const double* stateOld,
                                               double* stateNew, double* residual, double* tangent,
                                               double* pointStress, double* averageStress,
                                               const std::optional<double>& temperature) const {
  const auto cells = [&](int, const double* dNdx) { return PlanarCell<D>{numNodes_, dNdx}; };
  evaluateCell<PlanarCell<D>>(cells, x, u, material, stateOld, stateNew, residual, tangent,
                              pointStress, averageStress, temperature);
}

void ProjectedDilatationKernel::evaluateRing(const double* x, const double* u,
                                             const Material& material, const double* stateOld,
                                             double* stateNew, double* residual, double* tangent,
                                             double* pointStress, double* averageStress,
                                             const std::optional<double>& temperature) const {
  const int n = numNodes_;
  double radius[PressureSpace::kMaxPoints];
  for (int q = 0; q < numPoints_; ++q) {
    double point[3];
    interpolatePosition(n, x, &N_[q * n], point);
    radius[q] = point[0];
  }
  const auto cells = [&](int q, const double* dNdx) {
    return RingCell{n, dNdx, &N_[q * n], radius[q]};
  };
  evaluateCell<RingCell>(cells, x, u, material, stateOld, stateNew, residual, tangent, pointStress,
                         averageStress, temperature);
}

template class PlanarOrRingKernel<ProjectedDilatationKernel>;
// Out of line too (evaluate(), inline in the header, may be instantiated elsewhere).
template void ProjectedDilatationKernel::evaluatePlanar<2>(const double*, const double*,
                                                           const Material&, const double*, double*,
                                                           double*, double*, double*, double*,
                                                           const std::optional<double>&) const;
template void ProjectedDilatationKernel::evaluatePlanar<3>(const double*, const double*,
                                                           const Material&, const double*, double*,
                                                           double*, double*, double*, double*,
                                                           const std::optional<double>&) const;

}  // namespace contactlab
