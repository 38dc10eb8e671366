#include "algorithms/ThresholdLoop.hpp"

#include "algorithms/StaticSolver.hpp"

namespace contactlab {

std::string ThresholdLoop::failureMessage() const {
  return "friction thresholds still moved after " + std::to_string(updates()) +
         " fixed-point updates (Algorithm/Max Threshold Iterations)";
}

void ThresholdLoop::count(StepReport& report) const {
  ++report.thresholdIterations;
}

}  // namespace contactlab
