#include "formulations/Lagrange.hpp"

namespace contactlab {

Lagrange::Lagrange(double cn, double ct)
    : MultiplierLaw(cn, ct, "active-set constants c_n and c_t must be > 0") {}

// The multiplier p is the force; c_n only picks the active set.
void Lagrange::writeNormalRow(const LawInput& in, const PointState& s, LawOutput& out) const {
  const int g = 0, p = 1 + in.nt;
  out.r[g] = -s.w * in.p;
  jacobian(out, s, g, p) = -s.w;
  out.pressure = in.p;
}

// tau Lambda: the multiplier Lambda (the slip direction) carries the friction force. Threshold
// mu p once p > 0; before, mu (p - c_n g), already positive on a first iterate that starts in
// contact with p = 0 (both mu p at convergence, where g = 0 on active points).
void Lagrange::writeFrictionRow(const LawInput& in, const PointState& s, int k,
                                LawOutput& out) const {
  const int nt = in.nt, g = 0, p = 1 + nt, v = 1 + k, L = 2 + nt + k;
  const double w = s.w, tau = s.tau, cn = s.cn;
  out.r[v] = w * tau * in.Lambda[k];
  if (!s.thresholdFrozen) {
    jacobian(out, s, v, p) = w * in.mu * in.Lambda[k];
    if (!s.tauFromPressure) jacobian(out, s, v, g) = -w * in.mu * cn * in.Lambda[k];
  }
  jacobian(out, s, v, L) = w * tau;
  out.tangentialTraction[k] = -tau * in.Lambda[k];
}

}  // namespace contactlab
