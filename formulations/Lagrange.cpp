#include "formulations/Lagrange.hpp"

#include "formulations/BallProjection.hpp"

#include <algorithm>
#include <stdexcept>

namespace contactlab {

Lagrange::Lagrange(double cn, double ct) : cn_(cn), ct_(ct) {
  if (!(cn > 0) || !(ct > 0))
    throw std::invalid_argument("active-set constants c_n and c_t must be > 0");
}

void Lagrange::evaluate(const LawInput& in, LawOutput& out) const {
  const int nt = in.nt, n = size(nt);
  const int g = 0, p = 1 + nt, lam = 2 + nt;
  const double w = in.weight;
  out = LawOutput{};
  auto J = [&](int i, int j) -> double& { return out.J[i * n + j]; };
  const double cn = cn_ * in.coefficientScale, ct = ct_ * in.coefficientScale;

  const double pHat = in.p - cn * in.gap;
  const bool closed = in.frozenStatus >= 0 ? in.frozenStatus > 0 : pHat >= 0;
  out.indicator = pHat;
  const double SR = closed ? 1.0 : 0.0;
  out.r[g] = -w * in.p;
  J(g, p) = -w;
  out.r[p] = -(w / cn) * (in.p - SR * pHat);
  J(p, p) = -(w / cn) * (1 - SR);
  J(p, g) = -w * SR;
  out.pressure = in.p;
  out.status = closed ? ContactStatus::Stick : ContactStatus::Free;
  if (nt == 0) return;

  std::array<double, 2> LamHat{};
  for (int k = 0; k < nt; ++k)
    LamHat[k] = in.Lambda[k] + ct * in.slip[k];
  const BallProjection b = projectOnBall(LamHat, nt, 1.0, in.frozenStatus);
  out.frictionIndicator = b.excess;
  const bool thresholdFrozen = in.frozenThreshold >= 0;
  // Threshold mu (p - c_n g): equal to mu p at convergence (g = 0 on active points), and
  // already positive on a first iterate that starts in contact with p = 0.
  const double tau = thresholdFrozen ? in.frozenThreshold : in.mu * pHat;
  // Zero threshold (p = 0 on a closed point, up to round-off): no friction, and Lambda (a
  // direction) is undefined; its rows take the open branch Lambda = 0 so the Jacobian stays
  // regular.
  if (!closed || frictionThresholdIsRoundoff(tau, in, cn)) {
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
    out.r[v] = w * tau * in.Lambda[k];
    if (!thresholdFrozen) {
      J(v, p) = w * in.mu * in.Lambda[k];
      J(v, g) = -w * in.mu * cn * in.Lambda[k];
    }
    J(v, L) = w * tau;
    out.r[L] = w * (in.Lambda[k] - SR * b.P[k]);
    for (int j = 0; j < nt; ++j) {
      const double D = b.D[k * nt + j];
      J(L, lam + j) = w * ((k == j ? 1.0 : 0.0) - SR * D);
      J(L, 1 + j) = -w * SR * D * ct;
    }
    out.tangentialTraction[k] = -tau * in.Lambda[k];
  }
  out.threshold = tau;
  if (closed) out.status = b.inside ? ContactStatus::Stick : ContactStatus::Slip;
}

}  // namespace contactlab
