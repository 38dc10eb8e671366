#include "formulations/AugmentedLagrangian.hpp"

namespace contactlab {

AugmentedLagrangian::AugmentedLagrangian(double rn, double rt)
    : MultiplierLaw(rn, rt, "augmentation coefficients r_n and r_t must be > 0") {}

// The augmented pressure S_R p^ is the force: it is zero on open points, whatever p.
void AugmentedLagrangian::writeNormalRow(const LawInput& in, const PointState& s,
                                         LawOutput& out) const {
  const int g = 0, p = 1 + in.nt;
  const double w = s.w, SR = s.SR, rn = s.cn;
  out.r[g] = -w * SR * s.pHat;
  jacobian(out, s, g, g) = w * SR * rn;
  jacobian(out, s, g, p) = -w * SR;
  out.pressure = SR * s.pHat;
}

// S_R tau P_B(Lambda^): the friction force of the augmented friction multiplier.
void AugmentedLagrangian::writeFrictionRow(const LawInput& in, const PointState& s, int k,
                                           LawOutput& out) const {
  const int nt = in.nt, g = 0, p = 1 + nt, lam = 2 + nt, v = 1 + k;
  const double w = s.w, SR = s.SR, tau = s.tau, rt = s.ct;
  const double dTauDp = s.thresholdFrozen ? 0.0 : in.mu;
  const double dTauDg = s.thresholdFrozen ? 0.0 : -in.mu * s.cn;
  const BallProjection& b = s.ball;
  out.r[v] = w * SR * tau * b.P[k];
  jacobian(out, s, v, g) = w * SR * dTauDg * b.P[k];
  jacobian(out, s, v, p) = w * SR * dTauDp * b.P[k];
  for (int j = 0; j < nt; ++j) {
    const double D = b.D[k * nt + j];
    jacobian(out, s, v, 1 + j) = w * SR * tau * D * rt;
    jacobian(out, s, v, lam + j) = w * SR * tau * D;
  }
  out.tangentialTraction[k] = -SR * tau * b.P[k];
}

}  // namespace contactlab
