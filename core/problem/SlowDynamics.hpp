#pragma once
// Slow-dynamics regularization (the seed's "dynamique régularisante ou lente", after Jourdan's
// thesis, 1995): the tangent gains c M with c = alpha / (timeScale * dt)^2, dt the load step's
// time increment, M the mass matrix from each material's density. With `inertiaInResidual` the
// residual gains the matching inertia force c M (u - u_n - dt v_n) (an implicit Euler
// acceleration; v_n from the last two converged steps, zero at the first): the seed's three
// cases are then parameter choices,
//   real dynamics        alpha = 1, timeScale = the physical seconds per unit of load time
//   slow dynamics 1      alpha = 1 (real mass), timeScale large (c M negligible: ~1e-15 K)
//   slow dynamics 2      alpha small (small mass), timeScale small
// Without it only the tangent is regularized: Newton solves (c M + K) dx = -R(x), the seed's
// prediction-correction with the static residual, so a converged state is exactly static.
namespace contactlab {

struct SlowDynamics {
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

}  // namespace contactlab
