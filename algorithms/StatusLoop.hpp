#pragma once
// The contact statuses (open or closed; stick and slip follow the iterate) as a loop: as a
// fixed point, frozen at the last update while Newton runs; an update that changes a status
// restarts Newton, at most Algorithm/Max Status Iterations times per geometry update.
#include "algorithms/FixedPointLoop.hpp"
#include "formulations/ContactControls.hpp"

namespace contactlab {

class StatusLoop : public FixedPointLoop {
 public:
  StatusLoop(ContactControls& controls, bool inNewton, int maxUpdates)
      : FixedPointLoop(
            {"statuses", "statuses-not-converged", "contact statuses still changed after ",
             " fixed-point updates (Algorithm/Max Status Iterations)",
             &StepReport::statusIterations},
            inNewton, maxUpdates),
        controls_(controls) {}

  void freeze() override { controls_.freezeStatuses(true); }
  bool update(const Vector& x, double t) override { return controls_.updateStatuses(x, t) > 0; }
  bool changesStatuses() const override { return true; }
  // A forced point's frozen status is the forced one: the model's law decides it again.
  bool reviseForcedState(const Vector& x, double t) override { return update(x, t); }

 protected:
  void release() override { controls_.freezeStatuses(false); }

 private:
  ContactControls& controls_;
};

}  // namespace contactlab
