#include "formulations/AugmentedLagrangian.hpp"

#include "formulations/BallProjection.hpp"

#include <algorithm>
#include <stdexcept>

namespace contactlab {

AugmentedLagrangian::AugmentedLagrangian(double rn, double rt) : rn_(rn), rt_(rt) {
  if (!(rn > 0) || !(rt > 0))
    throw std::invalid_argument("augmentation coefficients r_n and r_t must be > 0");
}

void AugmentedLagrangian::evaluate(const LawInput& in, LawOutput& out) const {
  const int nt = in.nt, n = size(nt);
  const int g = 0, p = 1 + nt, lam = 2 + nt;
  const double w = in.weight;
  out = LawOutput{};
  auto J = [&](int i, int j) -> double& { return out.J[i * n + j]; };
  const double rn = rn_ * in.coefficientScale, rt = rt_ * in.coefficientScale;

  const double pHat = in.p - rn * in.gap;
  const bool closed = in.frozenStatus >= 0 ? in.frozenStatus > 0 : pHat >= 0;
  out.indicator = pHat;
  const double SR = closed ? 1.0 : 0.0;
  out.r[g] = -w * SR * pHat;
  J(g, g) = w * SR * rn;
  J(g, p) = -w * SR;
  out.r[p] = -(w / rn) * (in.p - SR * pHat);
  J(p, p) = -(w / rn) * (1 - SR);
  J(p, g) = -w * SR;
  out.pressure = SR * pHat;
  out.status = closed ? ContactStatus::Stick : ContactStatus::Free;
  if (nt == 0) return;

  std::array<double, 2> LamHat{};
  for (int k = 0; k < nt; ++k)
    LamHat[k] = in.Lambda[k] + rt * in.slip[k];
  const BallProjection b = projectOnBall(LamHat, nt, 1.0, in.frozenStatus);
  out.frictionIndicator = b.excess;
  const bool thresholdFrozen = in.frozenThreshold >= 0;
  const double tau = thresholdFrozen ? in.frozenThreshold : in.mu * pHat;
  const double dTauDp = thresholdFrozen ? 0.0 : in.mu;
  const double dTauDg = thresholdFrozen ? 0.0 : -in.mu * rn;
  // A closed point with a zero threshold (p^ = 0, e.g. surfaces just touching, up to the
  // round-off of their gap) transmits no friction and Lambda = lambda_t / (mu lambda_n) is
  // undefined there: its friction rows take the open branch (Lambda = 0), a piece of the
  // generalized Jacobian that stays regular.
  if (frictionThresholdIsRoundoff(tau, in, rn)) {
    for (int k = 0; k < nt; ++k) {
      out.r[lam + k] = w * in.Lambda[k];
      J(lam + k, lam + k) = w;
    }
    if (closed && (in.frozenStatus == 2 || in.frozenStatus == kSlipOnset))
      out.status = ContactStatus::Slip;  // as frozen
    return;
  }
  for (int k = 0; k < nt; ++k) {
    const int v = 1 + k, L = lam + k;
    out.r[v] = w * SR * tau * b.P[k];
    J(v, g) = w * SR * dTauDg * b.P[k];
    J(v, p) = w * SR * dTauDp * b.P[k];
    out.r[L] = w * (in.Lambda[k] - SR * b.P[k]);
    for (int j = 0; j < nt; ++j) {
      const double D = b.D[k * nt + j];
      J(v, 1 + j) = w * SR * tau * D * rt;
      J(v, lam + j) = w * SR * tau * D;
      J(L, lam + j) = w * ((k == j ? 1.0 : 0.0) - SR * D);
      J(L, 1 + j) = -w * SR * D * rt;
    }
    out.tangentialTraction[k] = -SR * tau * b.P[k];
  }
  out.threshold = SR * tau;
  if (closed) out.status = b.inside ? ContactStatus::Stick : ContactStatus::Slip;
}

}  // namespace contactlab
