#pragma once
// Exact Lagrange multipliers with an active set (primal-dual active set, a semi-smooth Newton
// on the complementarity functions of contact and Coulomb friction), at one point:
//   active set             S_R = 1 if p - c_n g >= 0; stick if ||Lambda + c_t v|| < 1
//   R_u  += -p dg + tau Lambda . dv         (the multipliers carry the forces; the threshold
//                                           tau = mu p once p > 0, mu p^ = mu (p - c_n g)
//                                           before, so that a point closed with p = 0 has one)
//   R_p   = -(1/c_n) (p - S_R (p - c_n g))  (active: g = 0; inactive: p = 0)
//   R_Lam = Lambda - S_R P_B(Lambda + c_t v)   (stick: v = 0; slip: Lambda = slip direction)
// times the point's weight. c_n, c_t only pick the active set: the solution does not depend on
// them, unlike the augmented Lagrangian's equilibrium, which carries p^ = p - r_n g.
#include "formulations/MultiplierLaw.hpp"

namespace contactlab {

class Lagrange : public MultiplierLaw {
 public:
  Lagrange(double cn, double ct);
  std::string name() const override { return "lagrange"; }
  // J(g, p) = -w always, J(p, g) = -w only on a closed point: not symmetric at an open one.
  bool symmetricJacobian(int /*nt*/) const override { return false; }
  bool coefficientsEnterForces() const override { return false; }

 private:
  void writeNormalRow(const LawInput& in, const PointState& s, LawOutput& out) const override;
  // tau = mu (p - c_n g) is not multiplied by S_R: an open point must not transmit it.
  bool openPointCarriesNoFriction() const override { return true; }
  void writeFrictionRow(const LawInput& in, const PointState& s, int k,
                        LawOutput& out) const override;
  double transmittedThreshold(const PointState& s) const override { return s.tau; }
  // The normal force is p: a threshold mu p^ at an iterate deep in its master (p^ >> p) would
  // let friction exceed mu times the normal force the point applies (doc/algorithms.md
  // "Lagrange's threshold").
  bool thresholdFromPressure() const override { return true; }
};

}  // namespace contactlab
