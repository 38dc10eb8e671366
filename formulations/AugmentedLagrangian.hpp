#pragma once
// The seed's augmented Lagrangian ("methode continue", doc/theory.md), at one point:
//   augmented pressure     p^ = p - r_n g            (seed: lambda^_n = lambda_n - r_n d_n)
//   contact status         S_R = 1 if p^ >= 0         (seed: lambda^_n <= 0)
//   augmented friction     Lambda^ = Lambda + r_t v,  S_f = 1 if ||Lambda^|| < 1 (stick)
//   R_u  += -S_R p^ dg + S_R mu p^ P_B(Lambda^) . dv   (= -(F_cont + F_frot))
//   R_p   = -(1/r_n) (p - S_R p^)                       (= F~_cont)
//   R_Lam = S_R (Lambda - P_B(Lambda^)) + (1 - S_R) Lambda   (= F~_frot)
// with P_B the projection on the unit ball (stick: Lambda^, slip: Lambda^/||Lambda^||), each
// term times the point's weight. Separated points (p = 0, g > 0) get p^ < 0, S_R = 0; closed
// points under compression (g = 0, p > 0) get S_R = 1. The Jacobian is the generalized one:
// exact on each status piece, the piece chosen by the current statuses.
#include "formulations/MultiplierLaw.hpp"

namespace contactlab {

class AugmentedLagrangian : public MultiplierLaw {
 public:
  // rn, rt > 0: augmentation coefficients (pressure per length; inverse length).
  AugmentedLagrangian(double rn, double rt);
  std::string name() const override { return "augmented-lagrangian"; }
  // Frictionless: J(g, p) = J(p, g) = -w SR on every piece. The threshold mu p^ couples the
  // friction rows to the normal ones one way only.
  bool symmetricJacobian(int nt) const override { return nt == 0; }

 private:
  void writeNormalRow(const LawInput& in, const PointState& s, LawOutput& out) const override;
  // Every friction term carries S_R: an open point's rows are zero without a branch of its own.
  bool openPointCarriesNoFriction() const override { return false; }
  void writeFrictionRow(const LawInput& in, const PointState& s, int k,
                        LawOutput& out) const override;
  double transmittedThreshold(const PointState& s) const override { return s.SR * s.tau; }
};

}  // namespace contactlab
