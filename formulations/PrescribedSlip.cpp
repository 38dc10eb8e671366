#include "formulations/PrescribedSlip.hpp"

#include <cmath>
#include <vector>

namespace contactlab {

namespace {

// The symmetry planes' directions in the tangent plane, orthonormalized: 0, 1 or 2 of them.
std::vector<std::array<double, 2>> symmetricDirections(
    int nt, const std::vector<std::array<double, 2>>& symmetric) {
  std::vector<std::array<double, 2>> basis;
  for (std::array<double, 2> q : symmetric) {
    if (nt == 1) q[1] = 0;
    if (std::hypot(q[0], q[1]) <= 0.5) continue;  // the plane's normal is the contact's
    for (const auto& b : basis) {
      const double d = q[0] * b[0] + q[1] * b[1];
      q[0] -= d * b[0];
      q[1] -= d * b[1];
    }
    const double norm = std::hypot(q[0], q[1]);
    if (norm <= 0.5) continue;  // the earlier planes span it
    basis.push_back({q[0] / norm, q[1] / norm});
  }
  return basis;
}

}  // namespace

PrescribedSlip prescribedSlip(const std::vector<double>& B, int nt, int nu,
                              const std::vector<char>& free,
                              const std::vector<std::vector<double>>& removed,
                              const std::vector<std::array<double, 2>>& symmetric) {
  PrescribedSlip s;
  if (nt == 0) return s;
  const auto bySymmetry = symmetricDirections(nt, symmetric);
  if (static_cast<int>(bySymmetry.size()) >= nt) {
    s.prescribed = nt;
    return s;
  }
  // Gram matrices of the slip rows over the allowed motion (M = B P B^T, P the projector on the
  // free dofs less the removed directions) and over all dofs (scale).
  double M[2][2] = {{0, 0}, {0, 0}}, scale = 0;
  for (int a = 0; a < nu; ++a)
    for (int k = 0; k < nt; ++k) {
      const double bk = B[(1 + k) * nu + a];
      scale += bk * bk;
      if (!free[a]) continue;
      for (int j = 0; j < nt; ++j)
        M[k][j] += bk * B[(1 + j) * nu + a];
    }
  for (const auto& c : removed) {
    double bc[2] = {0, 0};
    for (int k = 0; k < nt; ++k)
      for (int a = 0; a < nu; ++a)
        bc[k] += B[(1 + k) * nu + a] * c[a];
    for (int k = 0; k < nt; ++k)
      for (int j = 0; j < nt; ++j)
        M[k][j] -= bc[k] * bc[j];
  }
  // A direction is prescribed when the free part of its operator is below 0.1 % of the whole
  // (1e-6 on these squares): its multiplier would need a thousand times the traction it carries
  // to act on the free dofs it reaches. Not only round-off: a supported mortar slave node whose
  // row reaches a free master node by a sliver (the axisymmetric tube's joint end, 2.4e-5 of the
  // operator) took a multiplier of 8e7 at the next Newton iterate, and the step failed at every
  // cut. A direction that slides is far above: its free part is at least the square of a shape
  // value (the faceted hole's 2 %, 4e-4 here, is kept).
  const double tiny = 1e-6 * scale, roundoff = 1e-20 * scale;
  if (nt == 1) {
    s.prescribed = M[0][0] <= tiny ? 1 : 0;
    s.bySupports = M[0][0] <= roundoff;
    return s;
  }
  if (!bySymmetry.empty()) {
    // The one direction symmetry leaves (f, normal to the plane's q) is free if B moves it.
    const auto& q = bySymmetry.front();
    const double f[2] = {-q[1], q[0]};
    double fMf = 0;
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        fMf += f[k] * M[k][j] * f[j];
    if (fMf <= tiny) {
      s.prescribed = 2;
      return s;
    }
    s.prescribed = 1;
    s.basis = {{{f[0], q[0]}, {f[1], q[1]}}};  // columns f, q
    return s;
  }
  // 2 x 2: eigenvalues of the symmetric M, the smaller one's eigenvector prescribed.
  const double mean = 0.5 * (M[0][0] + M[1][1]);
  const double radius = std::hypot(0.5 * (M[0][0] - M[1][1]), M[0][1]);
  const double small = mean - radius, large = mean + radius;
  if (large <= tiny) {
    s.prescribed = 2;
    s.bySupports = large <= roundoff;
    return s;
  }
  if (small > tiny) return s;
  s.bySupports = small <= roundoff;
  // The eigenvector of `large` is free; its normal is prescribed.
  double fx = M[0][1], fy = large - M[0][0];
  if (std::hypot(fx, fy) <= 1e-300) fx = large - M[1][1], fy = M[0][1];
  const double norm = std::hypot(fx, fy);
  s.prescribed = 1;
  s.basis = {{{fx / norm, -fy / norm}, {fy / norm, fx / norm}}};  // columns (fx, fy), (-fy, fx)
  return s;
}

bool prescribedGap(const std::vector<double>& B, int nu, const std::vector<char>& free,
                   const std::vector<std::vector<double>>& removed) {
  double whole = 0, allowed = 0;
  for (int a = 0; a < nu; ++a) {
    whole += B[a] * B[a];
    if (free[a]) allowed += B[a] * B[a];
  }
  for (const auto& c : removed) {
    double bc = 0;
    for (int a = 0; a < nu; ++a)
      bc += B[a] * c[a];
    allowed -= bc * bc;
  }
  return whole > 0 && allowed <= 1e-6 * whole;
}

bool prescribedDirectionSlides(const PrescribedSlip& slip, int nt, const std::array<double, 2>& v,
                               double relativeMotion) {
  if (slip.prescribed == 0 || !slip.bySupports) return false;
  for (int c = nt - slip.prescribed; c < nt; ++c) {
    double along = 0;
    for (int i = 0; i < nt; ++i)
      along += slip.basis[i][c] * v[i];
    if (std::abs(along) > 1e-8 * relativeMotion) return true;
  }
  return false;
}

void dropPrescribedFriction(const PrescribedSlip& slip, int nt, double weight,
                            const std::array<double, 2>& Lambda, int size, LawOutput& out) {
  if (slip.prescribed == 0) return;
  const int first = 2 + nt;  // Lambda_1's law variable: (g, v.., p, Lambda..)
  // Q^T r and Q^T J on the Lambda rows; basis[i][c] = component i of column c.
  std::array<double, 2> r{};
  std::array<std::array<double, kMaxLawVariables>, 2> J{};
  for (int c = 0; c < nt; ++c)
    for (int i = 0; i < nt; ++i) {
      const double q = slip.basis[i][c];
      r[c] += q * out.r[first + i];
      for (int j = 0; j < size; ++j)
        J[c][j] += q * out.J[(first + i) * size + j];
    }
  for (int c = nt - slip.prescribed; c < nt; ++c) {
    // The prescribed direction's multiplier is 0: its row is w (q . Lambda).
    r[c] = 0;
    J[c].fill(0.0);
    for (int i = 0; i < nt; ++i) {
      r[c] += weight * slip.basis[i][c] * Lambda[i];
      J[c][first + i] = weight * slip.basis[i][c];
    }
  }
  for (int c = 0; c < nt; ++c) {
    out.r[first + c] = r[c];
    for (int j = 0; j < size; ++j)
      out.J[(first + c) * size + j] = J[c][j];
  }
}

}  // namespace contactlab
