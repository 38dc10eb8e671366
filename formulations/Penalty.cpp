#include "formulations/Penalty.hpp"

#include "formulations/BallProjection.hpp"

#include <algorithm>
#include <stdexcept>

namespace contactlab {

Penalty::Penalty(double epsN, double epsT) : epsN_(epsN), epsT_(epsT) {
  if (!(epsN > 0) || !(epsT > 0))
    throw std::invalid_argument("penalty coefficients eps_n and eps_t must be > 0");
}

void Penalty::evaluate(const LawInput& in, LawOutput& out) const {
  const int nt = in.nt, n = size(nt);
  const double w = in.weight;
  out = LawOutput{};
  auto J = [&](int i, int j) -> double& { return out.J[i * n + j]; };

  // Touching (g = 0) is closed: its contact stiffness is what holds a body that only its
  // contact supports at the first iterate (a zero-gap start under load control). With the open
  // piece there, the first tangent has no stiffness in the normal direction at all.
  const bool closed = in.frozenStatus >= 0 ? in.frozenStatus > 0 : in.gap <= 0;
  const double SR = closed ? 1.0 : 0.0;
  out.indicator = -epsN_ * in.gap;
  const double pressure = -SR * epsN_ * in.gap;
  out.r[0] = -w * pressure;
  J(0, 0) = w * SR * epsN_;
  out.pressure = pressure;
  out.status = closed ? ContactStatus::Stick : ContactStatus::Free;
  if (nt == 0 || !closed) return;

  const bool thresholdFrozen = in.frozenThreshold >= 0;
  const double tau = thresholdFrozen ? in.frozenThreshold : in.mu * pressure;
  const double dTauDg = thresholdFrozen ? 0.0 : -in.mu * epsN_;
  std::array<double, 2> trial{};
  for (int k = 0; k < nt; ++k)
    trial[k] = in.tangentialOld[k] + epsT_ * in.slip[k];
  const BallProjection b = projectOnBall(trial, nt, tau, in.frozenStatus);
  out.frictionIndicator = b.excess;
  for (int k = 0; k < nt; ++k) {
    const int v = 1 + k;
    out.r[v] = w * b.P[k];
    if (!b.inside) J(v, 0) = w * dTauDg * b.e[k];
    for (int j = 0; j < nt; ++j)
      J(v, 1 + j) = w * b.D[k * nt + j] * epsT_;
    out.tangentialTraction[k] = -b.P[k];
  }
  out.threshold = tau;
  out.status = b.inside ? ContactStatus::Stick : ContactStatus::Slip;
  // At zero penetration the threshold is zero and the point transmits no friction.
  out.frictionlessClosed = frictionThresholdIsRoundoff(tau, in, epsN_);
}

}  // namespace contactlab
