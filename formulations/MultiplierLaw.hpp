#pragma once
// What the Lagrange and augmented Lagrangian laws share, at one point: the multiplier unknowns
// (p, Lambda), the status picked by the augmented pressure p^ = p - c_n g (closed when p^ >= 0,
// or as frozen), stick/slip by the projection of Lambda^ = Lambda + c_t v on the unit ball,
// and the same constraint rows
//   R_p   = -(1/c_n) (p - S_R p^)                     (closed: g = 0; open: p = 0)
//   R_Lam = Lambda - S_R P_B(Lambda^)                 (Lambda = 0 where no friction acts)
// times the point's weight. The two laws differ only in what the equilibrium rows (g, v) carry,
// which a subclass writes: the multipliers themselves (Lagrange) or the augmented ones
// (augmented Lagrangian). c_n, c_t are the augmentation coefficients r_n, r_t of the latter.
#include "formulations/BallProjection.hpp"
#include "formulations/ContactLaw.hpp"

namespace contactlab {

class MultiplierLaw : public ContactLaw {
 public:
  bool hasMultipliers() const final { return true; }
  void evaluate(const LawInput& in, LawOutput& out) const final;
  double normalCoefficient() const final { return cn_; }

 protected:
  // The point's quantities, computed once, from which a subclass writes its equilibrium rows.
  struct PointState {
    int n = 0;      // size(nt): the row length of LawOutput::J
    double w = 0;   // weight
    double cn = 0;  // c_n and c_t times the local coefficient scale
    double ct = 0;
    double pHat = 0;      // p - c_n g
    bool closed = false;  // the contact status in use (natural or frozen)
    double SR = 0;        // 1 closed, 0 open
    bool thresholdFrozen = false;
    // Friction threshold: the frozen one, or mu p^, or mu p where thresholdFromPressure says so
    // (tauFromPressure).
    double tau = 0;
    bool tauFromPressure = false;
    BallProjection ball;  // of Lambda^ = Lambda + c_t v
  };

  // cn, ct > 0; otherwise throws std::invalid_argument with `notPositive` (one sentence that
  // names the coefficients as the law's documentation does).
  MultiplierLaw(double cn, double ct, const char* notPositive);

  static double& jacobian(LawOutput& out, const PointState& s, int row, int column) {
    return out.J[row * s.n + column];
  }

  // The normal equilibrium row g: out.r[0], its row of out.J and out.pressure.
  virtual void writeNormalRow(const LawInput& in, const PointState& s, LawOutput& out) const = 0;
  // Whether an open point's friction rows take the branch Lambda = 0 of a zero threshold. A law
  // whose friction rows are not multiplied by S_R needs it; the others give those rows zero.
  virtual bool openPointCarriesNoFriction() const = 0;
  // The friction equilibrium row 1 + k of a point that carries friction: out.r[1 + k], its row
  // of out.J and out.tangentialTraction[k].
  virtual void writeFrictionRow(const LawInput& in, const PointState& s, int k,
                                LawOutput& out) const = 0;
  // Whether the threshold is mu p once the multiplier p is positive (mu p^ before): a law whose
  // normal force is p itself, not p^.
  virtual bool thresholdFromPressure() const { return false; }
  // The friction threshold the point transmits (LawOutput::threshold).
  virtual double transmittedThreshold(const PointState& s) const = 0;

 private:
  const double cn_, ct_;
};

}  // namespace contactlab
