#include "algorithms/StatusLoop.hpp"

#include "algorithms/StaticSolver.hpp"

namespace contactlab {

std::string StatusLoop::failureMessage() const {
  return "contact statuses still changed after " + std::to_string(updates()) +
         " fixed-point updates (Algorithm/Max Status Iterations)";
}

void StatusLoop::count(StepReport& report) const {
  ++report.statusIterations;
}

}  // namespace contactlab
