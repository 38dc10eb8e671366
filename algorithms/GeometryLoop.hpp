#pragma once
// The geometry (each slave point's pairing with a master point, and the normal there) as a
// loop. In Newton, the system re-pairs at every iterate (NewtonRequest::geometryInNewton). As a
// fixed point, it is re-paired at the converged iterate; a pairing that moved restarts Newton,
// at most Newton/Max Geometry Iterations times per step, and gives the status and threshold
// fixed points a fresh cap (each new pairing starts them over: a sliding step needs a few
// threshold updates per geometry update, and their total over the step may pass one cap).
#include "algorithms/FixedPointLoop.hpp"
#include "core/problem/NonlinearSystem.hpp"

#include <string>
#include <vector>

namespace contactlab {

class GeometryLoop : public FixedPointLoop {
 public:
  // tolerance: Newton/Geometry Tolerance, relative to the step's reference residual;
  // absoluteTolerance: Newton/Absolute Tolerance, its floor.
  GeometryLoop(NonlinearSystem& system, bool inNewton, int maxUpdates, double tolerance,
               double absoluteTolerance)
      : FixedPointLoop(
            {"geometry", "geometry-not-converged", "the contact geometry still moved after ",
             " updates (Newton/Max Geometry Iterations)", &StepReport::geometryIterations},
            inNewton, maxUpdates),
        system_(system),
        tolerance_(tolerance),
        absoluteTolerance_(absoluteTolerance) {}

  bool update(const Vector& x, double t) override { return system_.updateGeometry(x, t); }
  bool renewsInnerCaps() const override { return true; }
  MovedStateTest testMovedState(const Vector& x, double t, double reference,
                                Vector& residual) override;
  // At the cap, says whether the residual at the updated geometry had stopped falling, and
  // which Geometry Tolerance would have accepted it.
  std::string failureMessage() const override;
  // The residual at the updated geometry ended above the step's first one and 100 times above
  // the lowest it reached (StaticSolver's geometry retry then puts the geometry in Newton).
  bool diverged() const override;
  // The period of the residual at the updated geometry: 2 or 3 where its last values repeat those
  // one period before, each to 1e-3, over two periods (a pairing that sends the iterate to another,
  // which sends it back); 0 otherwise. Said in the failure only: a cycle is not handed to the
  // geometry retry, which does not break it (doc/algorithms.md "Geometry retry").
  int cyclePeriod() const;

 protected:
  void release() override { relativeResiduals_.clear(); }

 private:
  NonlinearSystem& system_;
  double tolerance_, absoluteTolerance_;
  std::vector<double> relativeResiduals_;  // each moved-state test this step, / the reference
};

}  // namespace contactlab
