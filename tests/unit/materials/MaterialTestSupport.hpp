#pragma once
// Helpers shared by the constitutive-law tests: a finite- or small-strain evaluation, a tangent
// against central differences, random deformation gradients, rotations, diagonal stretches,
// the Cauchy stress of P, the largest entrywise difference of two tensors.
#include "core/materials/Material.hpp"
#include "core/materials/Tensor3.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <gtest/gtest.h>
#include <optional>
#include <random>
#include <vector>

namespace contactlab::test {

using tensor3::Mat3;

inline double maxAbs(const double* a, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i)
    m = std::max(m, std::abs(a[i]));
  return m;
}

// P and dP/dF of F from stateOld (nullptr for a law without internal variables); the trial
// state is discarded.
inline MaterialOutput evaluateF(const Material& m, const Mat3& F,
                                const double* stateOld = nullptr) {
  std::vector<double> stateNew(m.stateSize());
  MaterialInput in;
  in.F = F;
  in.stateOld = stateOld;
  MaterialOutput out;
  out.stateNew = stateNew.empty() ? nullptr : stateNew.data();
  m.evaluate(in, out);
  EXPECT_FALSE(out.failed) << m.name() << ": " << out.failure;
  return out;
}

// The same for a small-strain law: its stress and tangent at `strain` (Voigt, engineering
// shears), optionally at a temperature.
inline MaterialOutput evaluateStrain(const Material& m, const std::array<double, 6>& strain,
                                     const double* stateOld = nullptr,
                                     std::optional<double> temperature = std::nullopt) {
  std::vector<double> stateNew(m.stateSize());
  MaterialInput in;
  in.strain = strain;
  in.stateOld = stateOld;
  in.temperature = temperature;
  MaterialOutput out;
  out.stateNew = stateNew.empty() ? nullptr : stateNew.data();
  m.evaluate(in, out);
  EXPECT_FALSE(out.failed) << m.name() << ": " << out.failure;
  return out;
}

// max |tangent - central differences of f| / max |tangent| at x, with the step h: f maps N
// inputs to M outputs, tangent is their M x N derivative, row major.
template <std::size_t N, std::size_t M, class Function>
double centralDifferenceError(const Function& f, const std::array<double, N>& x,
                              const double* tangent, double h) {
  double err = 0.0;
  for (std::size_t b = 0; b < N; ++b) {
    std::array<double, N> plus = x, minus = x;
    plus[b] += h;
    minus[b] -= h;
    const std::array<double, M> fPlus = f(plus), fMinus = f(minus);
    for (std::size_t a = 0; a < M; ++a)
      err = std::max(err, std::abs(tangent[a * N + b] - (fPlus[a] - fMinus[a]) / (2.0 * h)));
  }
  return err / maxAbs(tangent, static_cast<int>(M * N));
}

// max |dPdF - central differences of P| / max |dPdF|, every evaluation from the same stateOld.
inline double dPdFError(const Material& m, const Mat3& F, const double* stateOld = nullptr) {
  const MaterialOutput out = evaluateF(m, F, stateOld);
  return centralDifferenceError<9, 9>([&](const Mat3& G) { return evaluateF(m, G, stateOld).P; }, F,
                                      out.dPdF.data(), 1e-6);
}

// F = I + G with G random, |G|_Frobenius uniform in [0.05, 0.5] (so det F > 0); plane-strain
// shaped (only the xy block of G) when planeStrain.
inline Mat3 randomF(std::mt19937& gen, bool planeStrain) {
  std::uniform_real_distribution<double> entry(-1.0, 1.0), size(0.05, 0.5);
  Mat3 G{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (!planeStrain || (i < 2 && j < 2)) G[i * 3 + j] = entry(gen);
  const double scale = size(gen) / std::sqrt(tensor3::contract(G, G));
  Mat3 F = tensor3::identity();
  for (int a = 0; a < 9; ++a)
    F[a] += scale * G[a];
  return F;
}

// Rotation by `angle` about the (normalized) `axis` (Rodrigues).
inline Mat3 rotation(std::array<double, 3> axis, double angle) {
  const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  for (double& a : axis)
    a /= n;
  const double c = std::cos(angle), s = std::sin(angle);
  Mat3 Q{};
  const Mat3 K = {0, -axis[2], axis[1], axis[2], 0, -axis[0], -axis[1], axis[0], 0};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      Q[i * 3 + j] = (i == j ? c : 0.0) + s * K[i * 3 + j] + (1.0 - c) * axis[i] * axis[j];
  return Q;
}

inline Mat3 diagonal(double a, double b, double c) {
  return {a, 0, 0, 0, b, 0, 0, 0, c};
}

// max_ij |a_ij - b_ij|.
inline double maxDifference(const Mat3& a, const Mat3& b) {
  double m = 0.0;
  for (int i = 0; i < 9; ++i)
    m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

// Cauchy stress P F^T / J.
inline Mat3 cauchy(const Mat3& P, const Mat3& F) {
  Mat3 sigma = tensor3::multiplyTranspose(P, F);
  const double J = tensor3::determinant(F);
  for (double& s : sigma)
    s /= J;
  return sigma;
}

}  // namespace contactlab::test
