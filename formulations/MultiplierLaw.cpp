#include "formulations/MultiplierLaw.hpp"

#include <cmath>
#include <stdexcept>

namespace contactlab {

MultiplierLaw::MultiplierLaw(double cn, double ct, const char* notPositive) : cn_(cn), ct_(ct) {
  if (!(cn > 0) || !(ct > 0)) throw std::invalid_argument(notPositive);
}

void MultiplierLaw::evaluate(const LawInput& in, LawOutput& out) const {
  const int nt = in.nt;
  const int g = 0, p = 1 + nt, lam = 2 + nt;
  PointState s;
  s.n = size(nt);
  s.w = in.weight;
  const double w = s.w;
  out = LawOutput{};
  auto J = [&](int i, int j) -> double& { return jacobian(out, s, i, j); };
  s.cn = cn_ * in.coefficientScale;
  s.ct = ct_ * in.coefficientScale;

  s.pHat = in.p - s.cn * in.gap;
  s.closed = in.frozenStatus >= 0 ? in.frozenStatus > 0 : s.pHat >= 0;
  out.indicator = s.pHat;
  s.SR = s.closed ? 1.0 : 0.0;
  writeNormalRow(in, s, out);
  out.r[p] = -(w / s.cn) * (in.p - s.SR * s.pHat);
  J(p, p) = -(w / s.cn) * (1 - s.SR);
  J(p, g) = -w * s.SR;
  out.status = s.closed ? ContactStatus::Stick : ContactStatus::Free;
  // r_p = -w g closed, -(w / c_n) p open (LawOutput::normalRowForce).
  out.normalRowForce = s.closed ? in.stiffnessScale : s.cn;
  if (nt == 0) return;

  std::array<double, 2> LamHat{};
  for (int k = 0; k < nt; ++k)
    LamHat[k] = in.Lambda[k] + s.ct * in.slip[k];
  s.ball = projectOnBall(LamHat, nt, 1.0, in.frozenStatus);
  out.frictionIndicator = s.ball.excess;
  s.thresholdFrozen = in.frozenThreshold >= 0;
  s.tauFromPressure = !s.thresholdFrozen && thresholdFromPressure() && in.p > 0;
  s.tau = s.thresholdFrozen   ? in.frozenThreshold
          : s.tauFromPressure ? in.mu * in.p
                              : in.mu * s.pHat;
  // A closed point with a zero threshold (p^ = 0, e.g. surfaces just touching, up to the
  // round-off of their gap) transmits no friction and Lambda = lambda_t / (mu lambda_n) is
  // undefined there: its friction rows take the open branch (Lambda = 0), a piece of the
  // generalized Jacobian that stays regular.
  if ((!s.closed && openPointCarriesNoFriction()) || frictionThresholdIsRoundoff(s.tau, in, s.cn)) {
    for (int k = 0; k < nt; ++k) {
      out.r[lam + k] = w * in.Lambda[k];
      J(lam + k, lam + k) = w;
    }
    out.frictionlessClosed = s.closed;
    if (s.closed && (in.frozenStatus == 2 || in.frozenStatus == kSlipOnset))
      out.status = ContactStatus::Slip;  // as frozen
    return;                              // Lambda carries no force here (frictionRowForce 0)
  }
  for (int k = 0; k < nt; ++k) {
    writeFrictionRow(in, s, k, out);
    const int L = lam + k;
    out.r[L] = w * (in.Lambda[k] - s.SR * s.ball.P[k]);
    for (int j = 0; j < nt; ++j) {
      const double D = s.ball.D[k * nt + j];
      J(L, lam + j) = w * ((k == j ? 1.0 : 0.0) - s.SR * D);
      J(L, 1 + j) = -w * s.SR * D * s.ct;
    }
  }
  out.threshold = transmittedThreshold(s);
  if (s.closed) out.status = s.ball.inside ? ContactStatus::Stick : ContactStatus::Slip;
  // Stick: r = -w c_t v, a slip whose force is E / h times it; slip: a direction error, whose
  // force is the threshold times it; open: no force.
  out.frictionRowForce = !s.closed       ? 0.0
                         : s.ball.inside ? in.stiffnessScale / s.ct
                                         : std::abs(s.tau);
}

}  // namespace contactlab
