#pragma once
// The start of a load step extrapolated from the last converged one (Newton/Extrapolation:
// linear; Abaqus' default "extrapolation = linear", code_aster's PREDICTION='EXTRAPOLE').
// A step driven by loads alone has no tangent predictor (its prescribed values do not move), so
// Newton, and the fixed points frozen at the step's start, begin where the last step ended:
// a tube expanded by a rising pressure starts each step with the statuses of the last one, and
// the status fixed point's first solve pushes the tube through the hole freely
// (doc/algorithms.md "Extrapolated start").
//
// The step's load increment is read off the residual at the plain start, r = R(u_n, t_{n+1})
// (the last state balanced R(u_n, t_n) = 0, so r = -(F(t_{n+1}) - F(t_n)) for loads, and the
// unbalance of the moved prescribed values for those). The start is
//     u_{n+1}^0 = u_n + a (u_n - u_{n-1}),   a = min(2, max(0, r.r_n / r_n.r_n)),
// r_n the last step's: the last increment scaled by this step's load increment projected on
// the last one's. A load held (r = 0) or turned back (a tube's pressure released after its
// peak: r.r_n < 0) gives a = 0, the plain start; a step twice as long, a = 2.
#include "core/problem/NonlinearSystem.hpp"

#include <Teuchos_RCP.hpp>

namespace contactlab {

class StepExtrapolation {
 public:
  // The plain start's residual of the step being solved: what record() keeps with the step (a
  // step recorded without it is not known: nothing to scale the next one's by).
  void beginStep(const Vector& plainResidual);
  // The step being solved has no plain residual (its assembly failed there): record() will not
  // know it.
  void skipStep() { hasPending_ = false; }
  // Records the converged step from `before` to `after` (the one begun last).
  void record(const Vector& before, const Vector& after);
  // Forgets the last step (a run started from a state whose history is not known).
  void clear() { known_ = false; }
  // The last converged step's increment and its plain start's residual (null until a step is
  // recorded): what a checkpoint keeps, and restore() takes back, so that a continued run
  // starts its next step as the uninterrupted run does.
  Teuchos::RCP<const Vector> increment() const { return known_ ? increment_ : Teuchos::null; }
  Teuchos::RCP<const Vector> load() const { return known_ ? load_ : Teuchos::null; }
  void restore(const Vector& increment, const Vector& load);
  // The factor a of the step begun last (0: start from u_n).
  double factor() const;
  // x := u + a (after - before) of the last recorded step, a = factor() > 0.
  void extrapolate(const Vector& u, double a, Vector& x) const;

  static constexpr double kLargestFactor = 2;

 private:
  Teuchos::RCP<Vector> increment_;  // after - before, the last converged step
  Teuchos::RCP<Vector> load_;       // its plain start's residual
  Teuchos::RCP<Vector> pending_;    // the plain start's residual of the step begun last
  bool hasPending_ = false;         // beginStep since the last record
  bool known_ = false;
};

}  // namespace contactlab
