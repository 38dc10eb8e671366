#pragma once
// Slow-dynamics regularization (the seed's "dynamique régularisante ou lente", after Jourdan's
// thesis, 1995), owned by the algorithm: before each step attempt it hands the system an inertia
// c M (NonlinearSystem::setInertia) with c = alpha / (timeScale * dt)^2, dt the step's increment
// of load time and M the mass matrix from each material's density; after a converged step it
// takes the state into its history and removes the term, so that what runs between steps (the
// outputs' assemblies, the uniqueness check) sees the static problem.
//
// With `inertiaInResidual` the residual gains the matching inertia force c M (u - u*), u* =
// u_n + dt v_n the implicit Euler predictor (v_n from the last two converged states, zero at the
// first): the seed's three cases are then parameter choices,
//   real dynamics        alpha = 1, timeScale = the physical seconds per unit of load time
//   slow dynamics 1      alpha = 1 (real mass), timeScale large (c M negligible: ~1e-15 K)
//   slow dynamics 2      alpha small (small mass), timeScale small
// Without it only the tangent is regularized: Newton solves (c M + K) dx = -R(x), the seed's
// prediction-correction with the static residual, so a converged state is exactly static.
#include "core/problem/NonlinearSystem.hpp"

namespace contactlab {

struct SlowDynamicsOptions {
  bool enabled = false;
  double alpha = 1.0;
  double timeScale = 1.0;
  bool lumped = false;
  bool inertiaInResidual = true;
  // c for a step of dt (load-time units); 0 when disabled or dt <= 0.
  double coefficient(double dt) const {
    if (!enabled || !(dt > 0)) return 0.0;
    const double h = timeScale * dt;
    return alpha / (h * h);
  }
};

class SlowDynamics {
 public:
  explicit SlowDynamics(SlowDynamicsOptions options) : options_(options) {}
  const SlowDynamicsOptions& options() const { return options_; }

  // Throws InputError when the regularization is enabled on a system without a mass.
  void requireMass(const NonlinearSystem& system) const;
  // The run starts from the state x0 at time t0 (at rest: no velocity).
  void start(const Vector& x0, double t0);
  // After start(): the state of the step before x0's and that step's length (a checkpoint's),
  // so that the next step's predictor moves with the velocity the uninterrupted run had.
  void restorePrevious(const Vector& previous, double previousStep);
  // What restorePrevious takes back: the state before the last converged one (null: none) and
  // the last step's length.
  Teuchos::RCP<const Vector> previousState() const { return previous_; }
  double previousStep() const { return previousStep_; }
  // Before an attempt at the step to time t: the system's inertia for it.
  void beginStep(NonlinearSystem& system, double t) const;
  // The step converged at x, t: x enters the history and the system is static again.
  void commit(NonlinearSystem& system, const Vector& x, double t);
  // The system without the term (after the run, whatever ended it).
  void end(NonlinearSystem& system) const;
  // The implicit Euler predictor u* for a step to time t (tests read it).
  Teuchos::RCP<Vector> predictor(double t) const;

 private:
  SlowDynamicsOptions options_;
  // The last two converged states and their times.
  Teuchos::RCP<Vector> current_, previous_;
  double time_ = 0, previousStep_ = 0;
};

}  // namespace contactlab
