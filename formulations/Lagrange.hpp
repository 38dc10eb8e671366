#pragma once
// Exact Lagrange multipliers with an active set (primal-dual active set, a semi-smooth Newton
// on the complementarity functions of contact and Coulomb friction), at one point:
//   active set             S_R = 1 if p - c_n g >= 0; stick if ||Lambda + c_t v|| < 1
//   R_u  += -p dg + mu p^ Lambda . dv       (the multipliers carry the forces; the threshold
//                                           mu p^, p^ = p - c_n g, is mu p at convergence)
//   R_p   = -(1/c_n) (p - S_R (p - c_n g))  (active: g = 0; inactive: p = 0)
//   R_Lam = Lambda - S_R P_B(Lambda + c_t v)   (stick: v = 0; slip: Lambda = slip direction)
// times the point's weight. c_n, c_t only pick the active set: the solution does not depend on
// them, unlike the augmented Lagrangian's equilibrium, which carries p^ = p - r_n g.
#include "formulations/ContactLaw.hpp"

namespace contactlab {

class Lagrange : public ContactLaw {
 public:
  Lagrange(double cn, double ct);
  std::string name() const override { return "lagrange"; }
  bool hasMultipliers() const override { return true; }
  void evaluate(const LawInput& in, LawOutput& out) const override;
  double normalCoefficient() const override { return cn_; }
  // J(g, p) = -w always, J(p, g) = -w only on a closed point: not symmetric at an open one.
  bool symmetricJacobian(int /*nt*/) const override { return false; }

 private:
  const double cn_, ct_;
};

}  // namespace contactlab
