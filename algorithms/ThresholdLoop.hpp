#pragma once
// The friction thresholds mu p as a loop: as a fixed point, frozen at the last update while
// Newton runs (Tresca friction), then updated from the converged pressures; an update that
// moves a threshold by more than Threshold Tolerance times the largest restarts Newton, at most
// Algorithm/Max Threshold Iterations times per geometry update.
#include "algorithms/FixedPointLoop.hpp"
#include "formulations/ContactControls.hpp"

namespace contactlab {

class ThresholdLoop : public FixedPointLoop {
 public:
  ThresholdLoop(ContactControls& controls, bool inNewton, int maxUpdates, double tolerance)
      : FixedPointLoop(
            {"thresholds", "thresholds-not-converged", "friction thresholds still moved after ",
             " fixed-point updates (Algorithm/Max Threshold Iterations)",
             &StepReport::thresholdIterations},
            inNewton, maxUpdates),
        controls_(controls),
        tolerance_(tolerance) {}

  void freeze() override { controls_.freezeThresholds(true); }
  bool update(const Vector& x, double t) override {
    return controls_.updateThresholds(x, t) > tolerance_;
  }
  // A point forced closed held the threshold it had when forced (ContactControls::forceStatus),
  // which its frozen threshold kept through the updates since: read from the law again, it may
  // move. Kept, a forced stick point could end with a traction above mu p and be reported
  // converged.
  bool reviseForcedState(const Vector& x, double t) override { return update(x, t); }

 protected:
  void release() override { controls_.freezeThresholds(false); }

 private:
  ContactControls& controls_;
  double tolerance_;
};

}  // namespace contactlab
