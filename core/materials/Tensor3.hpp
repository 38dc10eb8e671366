#pragma once
// Small dense 3x3 tensor helpers shared by the constitutive laws. A tensor is a row-major
// std::array<double, 9>: A[i * 3 + j] = A_ij (the layout of MaterialInput::F and
// MaterialOutput::P).
#include <array>
#include <cmath>

namespace contactlab::tensor3 {

using Mat3 = std::array<double, 9>;

inline Mat3 identity() {
  return {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
}

inline double trace(const Mat3& A) {
  return A[0] + A[4] + A[8];
}

inline double determinant(const Mat3& A) {
  return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
         A[2] * (A[3] * A[7] - A[4] * A[6]);
}

// Transpose of the cofactor matrix: A adj(A) = det(A) I. Defined for singular A too.
inline Mat3 adjugate(const Mat3& A) {
  return {A[4] * A[8] - A[5] * A[7], A[2] * A[7] - A[1] * A[8], A[1] * A[5] - A[2] * A[4],
          A[5] * A[6] - A[3] * A[8], A[0] * A[8] - A[2] * A[6], A[2] * A[3] - A[0] * A[5],
          A[3] * A[7] - A[4] * A[6], A[1] * A[6] - A[0] * A[7], A[0] * A[4] - A[1] * A[3]};
}

// A^-1 given det(A) != 0 (the caller has it already and decides what a singular A means).
inline Mat3 inverse(const Mat3& A, double detA) {
  Mat3 inv = adjugate(A);
  for (double& a : inv)
    a /= detA;
  return inv;
}

// A^T.
inline Mat3 transpose(const Mat3& A) {
  return {A[0], A[3], A[6], A[1], A[4], A[7], A[2], A[5], A[8]};
}

// A B.
inline Mat3 multiply(const Mat3& A, const Mat3& B) {
  Mat3 C{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        C[i * 3 + j] += A[i * 3 + k] * B[k * 3 + j];
  return C;
}

// A^T B (e.g. the right Cauchy-Green tensor C = F^T F).
inline Mat3 transposeMultiply(const Mat3& A, const Mat3& B) {
  Mat3 C{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        C[i * 3 + j] += A[k * 3 + i] * B[k * 3 + j];
  return C;
}

// A B^T (e.g. the left Cauchy-Green tensor b = F F^T).
inline Mat3 multiplyTranspose(const Mat3& A, const Mat3& B) {
  Mat3 C{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        C[i * 3 + j] += A[i * 3 + k] * B[j * 3 + k];
  return C;
}

// A : B = A_ij B_ij.
inline double contract(const Mat3& A, const Mat3& B) {
  double s = 0.0;
  for (int i = 0; i < 9; ++i)
    s += A[i] * B[i];
  return s;
}

// Eigenvalues and orthonormal eigenvectors of a symmetric A (its upper triangle is read), by
// cyclic Jacobi rotations: A = Q diag(values) Q^T, eigenvector a in column a (Q[i * 3 + a]).
// Accurate to round-off for equal and near-equal eigenvalues as well (then Q is some
// orthonormal basis of the eigenspace). Returns false when A is not finite or the rotations do
// not annihilate the off-diagonal part within 50 sweeps.
inline bool symmetricEigen(const Mat3& A, std::array<double, 3>& values, Mat3& Q) {
  double a[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      a[i][j] = i <= j ? A[i * 3 + j] : A[j * 3 + i];
  Q = identity();
  constexpr int kPairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = std::abs(a[0][1]) + std::abs(a[0][2]) + std::abs(a[1][2]);
    if (!std::isfinite(off + a[0][0] + a[1][1] + a[2][2])) return false;
    if (off == 0.0) {
      values = {a[0][0], a[1][1], a[2][2]};
      return true;
    }
    for (const auto& pq : kPairs) {
      const int p = pq[0], q = pq[1], r = 3 - p - q;
      const double apq = a[p][q];
      if (apq == 0.0) continue;
      const double g = 100.0 * std::abs(apq);
      if (sweep > 3 && std::abs(a[p][p]) + g == std::abs(a[p][p]) &&
          std::abs(a[q][q]) + g == std::abs(a[q][q])) {
        a[p][q] = a[q][p] = 0.0;  // below round-off of both diagonal entries
        continue;
      }
      // The rotation in the (p, q) plane that zeroes a_pq: t = tan(phi), cot(2 phi) = theta.
      const double theta = (a[q][q] - a[p][p]) / (2.0 * apq);
      double t = std::abs(theta) > 1e150 ? 0.5 / std::abs(theta)
                                         : 1.0 / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
      if (theta < 0.0) t = -t;
      const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
      a[p][p] -= t * apq;
      a[q][q] += t * apq;
      a[p][q] = a[q][p] = 0.0;
      const double arp = a[r][p], arq = a[r][q];
      a[r][p] = a[p][r] = c * arp - s * arq;
      a[r][q] = a[q][r] = s * arp + c * arq;
      for (int k = 0; k < 3; ++k) {
        const double qkp = Q[k * 3 + p], qkq = Q[k * 3 + q];
        Q[k * 3 + p] = c * qkp - s * qkq;
        Q[k * 3 + q] = s * qkp + c * qkq;
      }
    }
  }
  return false;
}

}  // namespace contactlab::tensor3
