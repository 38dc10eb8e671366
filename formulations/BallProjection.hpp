#pragma once
// Projection on the ball of radius rho in R^nt (nt <= 2) and its derivative: the return map of
// Coulomb friction. Inside (||x|| < rho, or x = 0): P = x, D = I. Outside: P = rho x/||x||,
// D = rho (I - e e^T)/||x|| with e = x/||x||.
#include <algorithm>
#include <array>
#include <cmath>

namespace contactlab {

struct BallProjection {
  std::array<double, 2> P{};
  std::array<double, 4> D{};  // row major nt x nt
  std::array<double, 2> e{};  // unit direction of x (zero when x = 0)
  bool inside = true;
  double excess = 0;  // (|x| - rho) / rho: < 0 inside, 0 on the sphere (the stick-slip switch)
};

// A status that takes the slip branch as at its onset: direction x/|x| with |x| held at the
// radius, D = I - e e^T. The Jacobian a sticking point (|x| < rho) takes as it starts to slip;
// the plain slip branch there would scale D by rho/|x| > 1 (the uniqueness diagnostic's
// slipping contact set).
constexpr int kSlipOnset = 4;

// `status` 1 (stick), 2 (slip) or kSlipOnset forces that branch (a status frozen by an
// algorithm); any other value lets x decide. A forced slip at x = 0 keeps a zero direction.
inline BallProjection projectOnBall(const std::array<double, 2>& x, int nt, double rho,
                                    int status = -1) {
  BallProjection b;
  double norm = 0;
  for (int k = 0; k < nt; ++k)
    norm += x[k] * x[k];
  norm = std::sqrt(norm);
  if (norm > 0)
    for (int k = 0; k < nt; ++k)
      b.e[k] = x[k] / norm;
  b.inside = status == 1 || (status != 2 && status != kSlipOnset && (norm < rho || norm == 0.0));
  b.excess = rho > 0 ? (norm - rho) / rho : (norm > 0 ? 1e300 : -1.0);
  const double scale = status == kSlipOnset ? 1.0 : rho / std::max(norm, 1e-300);
  for (int k = 0; k < nt; ++k) {
    b.P[k] = b.inside ? x[k] : rho * b.e[k];
    for (int j = 0; j < nt; ++j)
      b.D[k * nt + j] =
          b.inside ? (k == j ? 1.0 : 0.0) : scale * ((k == j ? 1.0 : 0.0) - b.e[k] * b.e[j]);
  }
  return b;
}

}  // namespace contactlab
