#pragma once
// Small dense 3x3 tensor helpers shared by the constitutive laws. A tensor is a row-major
// std::array<double, 9>: A[i * 3 + j] = A_ij (the layout of MaterialInput::F and
// MaterialOutput::P).
#include <array>

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

}  // namespace contactlab::tensor3
