#pragma once
// The contact statuses (open or closed; stick and slip follow the iterate) as a loop: as a
// fixed point, frozen at the last update while Newton runs; an update that changes a status
// restarts Newton, at most Algorithm/Max Status Iterations times per geometry update.
//
// An update that changes back exactly the points the last one changed is a two-update cycle:
// from then on, for the rest of the step, each update changes only the point whose frozen
// status the law contradicts most (the largest |p^|): at the edge of a contact zone a group of
// points can be in tension when frozen closed and penetrate when frozen open, together, update
// after update (doc/algorithms.md "Cycling").
// Such an update, when it opens points the iterate held closed, also lets the friction
// thresholds update before Newton restarts (cyclesAtFrozenSurroundings): a point whose frozen
// threshold is stale may have no status that holds (closed, its frozen friction pulls it into
// tension; open, it has none and penetrates), and scaling its coefficients does not help.
#include "algorithms/FixedPointLoop.hpp"
#include "formulations/ContactControls.hpp"

#include <cstddef>
#include <vector>

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
  bool update(const Vector& x, double t) override;
  bool changesStatuses() const override { return true; }
  bool cyclesAtFrozenSurroundings() const override { return thresholdsStale_; }
  // A forced point's frozen status is the forced one: the model's law decides it again.
  bool reviseForcedState(const Vector& x, double t) override { return update(x, t); }

 protected:
  void release() override {
    controls_.freezeStatuses(false);
    lastChanged_.clear();
    oneAtATime_ = false;
    thresholdsStale_ = false;
  }

 private:
  ContactControls& controls_;
  std::vector<std::size_t> lastChanged_;  // the points the last update changed (not forced)
  bool oneAtATime_ = false;
  // The last update opened back the points the one before closed.
  bool thresholdsStale_ = false;
};

}  // namespace contactlab
