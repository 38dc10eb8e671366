#include "algorithms/SlowDynamics.hpp"

#include "base/InputError.hpp"

namespace contactlab {

void SlowDynamics::requireMass(const NonlinearSystem& system) const {
  if (!options_.enabled) return;
  const std::string missing = system.massUnavailable();
  if (!missing.empty())
    throw InputError("the slow-dynamics regularization needs a mass, but " + missing +
                     " (Algorithm/slow-dynamics/Alpha scales the mass)");
}

void SlowDynamics::start(const Vector& x0, double t0) {
  if (!options_.enabled) return;
  current_ = Teuchos::rcp(new Vector(x0, Teuchos::Copy));
  previous_ = Teuchos::null;
  time_ = t0;
  previousStep_ = 0;
}

void SlowDynamics::restorePrevious(const Vector& previous, double previousStep) {
  if (!options_.enabled) return;
  previous_ = Teuchos::rcp(new Vector(previous, Teuchos::Copy));
  previousStep_ = previousStep;
}

Teuchos::RCP<Vector> SlowDynamics::predictor(double t) const {
  // u* = u_n + dt v_n with v_n = (u_n - u_(n-1)) / dt_n: the implicit Euler acceleration is
  // (u - u*) / dt^2. Written entry by entry as u_n + ratio (u_n - u_(n-1)), the rounding the
  // regression counts were recorded with.
  auto star = Teuchos::rcp(new Vector(*current_, Teuchos::Copy));
  if (previous_.is_null() || !(previousStep_ > 0)) return star;
  const double ratio = (t - time_) / previousStep_;
  auto s = star->getDataNonConst(0);
  auto c = current_->getData(0), p = previous_->getData(0);
  for (std::size_t i = 0; i < static_cast<std::size_t>(s.size()); ++i)
    s[i] += ratio * (c[i] - p[i]);
  return star;
}

void SlowDynamics::beginStep(NonlinearSystem& system, double t) const {
  if (!options_.enabled) return;
  InertiaTerm term;
  term.coefficient = options_.coefficient(t - time_);
  term.lumped = options_.lumped;
  if (options_.inertiaInResidual && term.coefficient > 0) term.reference = predictor(t);
  system.setInertia(term);
}

void SlowDynamics::commit(NonlinearSystem& system, const Vector& x, double t) {
  if (!options_.enabled) return;
  previous_ = current_;
  current_ = Teuchos::rcp(new Vector(x, Teuchos::Copy));
  previousStep_ = t - time_;
  time_ = t;
  system.setInertia({});
}

void SlowDynamics::end(NonlinearSystem& system) const {
  if (options_.enabled) system.setInertia({});
}

}  // namespace contactlab
