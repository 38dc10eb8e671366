#include "algorithms/StepExtrapolation.hpp"

#include <algorithm>
#include <stdexcept>

namespace contactlab {

namespace {
void copyInto(Teuchos::RCP<Vector>& into, const Vector& from) {
  if (into.is_null() || !into->getMap()->isSameAs(*from.getMap()))
    into = Teuchos::rcp(new Vector(from.getMap()));
  into->assign(from);
}
}  // namespace

void StepExtrapolation::beginStep(const Vector& plainResidual) {
  copyInto(pending_, plainResidual);
  hasPending_ = true;
}

void StepExtrapolation::record(const Vector& before, const Vector& after) {
  known_ = hasPending_;  // a step begun without its plain residual: nothing to scale by
  hasPending_ = false;
  if (!known_) return;
  copyInto(increment_, after);
  increment_->update(-1.0, before, 1.0);
  copyInto(load_, *pending_);
}

void StepExtrapolation::restore(const Vector& increment, const Vector& load) {
  copyInto(increment_, increment);
  copyInto(load_, load);
  known_ = true;
}

double StepExtrapolation::factor() const {
  if (!known_ || !hasPending_) return 0;
  const double last = load_->dot(*load_);
  if (!(last > 0)) return 0;
  return std::clamp(pending_->dot(*load_) / last, 0.0, kLargestFactor);
}

void StepExtrapolation::extrapolate(const Vector& u, double a, Vector& x) const {
  if (!known_) throw std::logic_error("StepExtrapolation: no converged step recorded");
  x.update(1.0, u, a, *increment_, 0.0);
}

}  // namespace contactlab
