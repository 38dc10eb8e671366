#pragma once
// One non-smooth part of the contact problem's p(x) (doc/algorithms.md "Three non-smooth things,
// one loop each": the contact statuses, the friction thresholds, the geometry) as StaticSolver
// drives it: either handed to Newton (the system updates it at every iterate) or a fixed point
// around the Newton solve, frozen while Newton runs and updated after it converged, with its own
// test and its own cap.
//
// StaticSolver holds the loops innermost first and runs them generically (doc/algorithms.md):
// after each converged Newton solve, the innermost fixed point whose update moves restarts
// Newton; the step ends when none moves, or when a loop's own test accepts the moved state. A
// preset is an ordered list of loops (composeLoops, algorithms/AlgorithmPresets.hpp), so a new
// nonlinearity is a new class here, not a new branch in the solver.
#include "algorithms/StepReport.hpp"
#include "base/LinearAlgebra.hpp"

#include <string>
#include <utility>

namespace contactlab {

class FixedPointLoop {
 public:
  // How a loop is named in reports and failures.
  struct Identity {
    std::string name;     // "statuses", "thresholds", "geometry"
    std::string failure;  // the step's failure at the cap: "statuses-not-converged", ...
    // The failure's message is capBefore + the count + capAfter ("contact statuses still
    // changed after " 30 " fixed-point updates (Algorithm/Max Status Iterations)").
    std::string capBefore, capAfter;
    int StepReport::*counter;  // the StepReport field that counts the updates that moved
  };
  // maxUpdates: the updates that moved allowed before the loop fails, counted from the step's
  // start or from the last time an enclosing loop renewed the cap (renewsInnerCaps).
  FixedPointLoop(Identity identity, bool inNewton, int maxUpdates)
      : identity_(std::move(identity)), inNewton_(inNewton), maxUpdates_(maxUpdates) {}
  virtual ~FixedPointLoop() = default;
  FixedPointLoop(const FixedPointLoop&) = delete;
  FixedPointLoop& operator=(const FixedPointLoop&) = delete;

  const std::string& name() const { return identity_.name; }
  bool inNewton() const { return inNewton_; }

  // At the start of each attempt at a step, before the predictor and the step's first
  // assembly: the cap starts over and whatever the loop freezes follows the iterate.
  void beginStep() {
    updates_ = 0;
    release();
  }
  // After the step's first assembly, for a fixed point: the state of that assembly becomes
  // the frozen one the first Newton solve runs with.
  virtual void freeze() {}
  // One fixed-point update at the converged Newton iterate x, t: whether it moved (a status
  // changed, a threshold moved beyond its tolerance, the pairing changed).
  virtual bool update(const Vector& x, double t) = 0;

  // The cap: StaticSolver fails the step with failure() when an update moves once the loop
  // has used maxUpdates(), and otherwise counts it (recordUpdate).
  int updates() const { return updates_; }
  int maxUpdates() const { return maxUpdates_; }
  const std::string& failure() const { return identity_.failure; }
  virtual std::string failureMessage() const {
    return identity_.capBefore + std::to_string(updates_) + identity_.capAfter;
  }
  // After a failure at the cap: whether the updates went away from a solution rather than
  // towards it or onto a floor (the geometry: GeometryLoop), so that going on the same way, with
  // a line search or a shorter step, cannot help.
  virtual bool diverged() const { return false; }
  void recordUpdate(StepReport& report) {
    ++updates_;
    ++(report.*identity_.counter);
  }
  void renewCap() { updates_ = 0; }
  // Whether an update that moved gives the loops inside it a fresh cap (the geometry: a new
  // pairing starts the statuses and thresholds over; a threshold update does not, so the
  // statuses' cap stays per geometry update).
  virtual bool renewsInnerCaps() const { return false; }
  // Whether the last update that moved undid the one before it: a two-update cycle at the state
  // the loops around it hold frozen (the statuses under friction thresholds that are stale).
  // StaticSolver then lets the next enclosing fixed point update before Newton restarts.
  virtual bool cyclesAtFrozenSurroundings() const { return false; }
  // Whether an update that moved changed contact statuses, which the cycling detector then
  // watches as it watches Newton's iterates (a status flipping between updates cycles too).
  virtual bool changesStatuses() const { return false; }

  // The loop's own test of a state its update moved: the residual there and the target under
  // which the fixed point has converged all the same (the geometry: Newton converged at a
  // pairing frozen at this very iterate, so a small change of the residual is convergence).
  struct MovedStateTest {
    bool tested = false;  // false: a moved update always restarts Newton
    double residual = 0;
    double target = 0;
  };
  virtual MovedStateTest testMovedState(const Vector& /*x*/, double /*t*/, double /*reference*/,
                                        Vector& /*residual*/) {
    return {};
  }
  // Once the cycling treatment's forced statuses are released: updates what the forcing held
  // frozen from the model's own law, and returns whether it moved (the forced state is then
  // not a solution).
  virtual bool reviseForcedState(const Vector& /*x*/, double /*t*/) { return false; }

 protected:
  // Releases what the loop freezes (beginStep).
  virtual void release() {}

 private:
  Identity identity_;
  bool inNewton_;
  int maxUpdates_;
  int updates_ = 0;
};

}  // namespace contactlab
