#pragma once
// Penalty contact with regularized Coulomb friction, at one point, no multipliers:
//   pressure     p = eps_n <-g>          (inexact: the surfaces interpenetrate by p / eps_n)
//   trial        q* = q_old + eps_t v    (q: tangential resistance, opposes slip)
//   return map   q = P_{B(mu p)}(q*)     (stick inside the cone, slip on it)
//   R_u += -p dg + q . dv
// times the point's weight; q_old is the resistance at the last converged step.
#include "formulations/ContactLaw.hpp"

namespace contactlab {

class Penalty : public ContactLaw {
 public:
  Penalty(double epsN, double epsT);
  std::string name() const override { return "penalty"; }
  bool hasMultipliers() const override { return false; }
  void evaluate(const LawInput& in, LawOutput& out) const override;
  double normalCoefficient() const override { return epsN_; }
  // Frictionless: w eps_n on the diagonal. The threshold mu eps_n <-g> couples the friction
  // rows to the gap one way only.
  bool symmetricJacobian(int nt) const override { return nt == 0; }
  bool coefficientsChangeSolution() const override { return true; }

 private:
  const double epsN_, epsT_;
};

}  // namespace contactlab
