#include "algorithms/GeometryLoop.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace contactlab {

FixedPointLoop::MovedStateTest GeometryLoop::testMovedState(const Vector& x, double t,
                                                            double reference, Vector& residual) {
  // Newton converged at a geometry frozen at this very iterate: when the update changes the
  // residual by less than the geometry tolerance, the fixed point has converged too.
  system_.assemble(x, t, &residual, false);
  MovedStateTest test;
  test.tested = true;
  test.residual = residual.norm2();
  test.target = std::max(absoluteTolerance_, tolerance_ * reference);
  if (reference > 0) relativeResiduals_.push_back(test.residual / reference);
  return test;
}

bool GeometryLoop::diverged() const {
  // Converging, the residual at the updated geometry falls by a factor of 5 to 10 per update.
  // Diverging: it ends above the step's first one and 100 times above the lowest it reached (the
  // NAFEMS roller under its force, frictionless node-to-segment: 4e2, 2e1, 9e1, 1e3, 4e4, then
  // 1e6 to 1e7 against 5e3 at the step's start). The frozen normal is the master's, which
  // rotates as the master deforms; the consistent tangent (the geometry in Newton with its full
  // terms) converges there.
  if (relativeResiduals_.empty()) return false;
  const double lowest = *std::min_element(relativeResiduals_.begin(), relativeResiduals_.end());
  const double last = relativeResiduals_.back();
  return last > 1.0 && last > 100.0 * lowest;
}

int GeometryLoop::cyclePeriod() const {
  // The fixed point of the seed-size tube's unloading under the fixed-point preset: 2.147,
  // 2.153, 2.147, 2.153, ... over 15 updates, Newton's first residual after each alternating
  // 5.326e-6, 2.801e-6. A frozen pairing and frozen statuses determine the converged iterate,
  // so two updates that came back to a residual to 1e-3 came back to a pairing; converging or
  // on a floor (the blade root's slivers: within a factor of 2), successive values differ by
  // far more. Two full periods, so that one coincidence does not count.
  constexpr double kSame = 1e-3;
  const auto same = [](double a, double b) { return std::abs(a - b) <= kSame * std::max(a, b); };
  const std::size_t n = relativeResiduals_.size();
  for (int period : {2, 3}) {
    const std::size_t p = period;
    if (n < 3 * p) continue;
    bool repeats = true;
    for (std::size_t i = n - 2 * p; i < n && repeats; ++i)
      repeats = same(relativeResiduals_[i], relativeResiduals_[i - p]);
    if (repeats) return period;
  }
  return 0;
}

std::string GeometryLoop::failureMessage() const {
  std::string message = FixedPointLoop::failureMessage();
  // Converging, the residual at the updated geometry falls by a factor of 5 to 10 per update
  // (doc/verification.md, the blade root); within a factor of 4 over the last 4 updates, it
  // sits on a floor the updates cannot lower: the hex27 blade root's mortar slivers, which
  // appear at one update and vanish at the next, hold it at 1.3e-6 to 2.3e-6.
  constexpr std::size_t kWindow = 4;
  constexpr double kStagnation = 4.0;
  if (diverged()) {
    // Not the cap's sentence: StaticSolver gives a diverging fixed point up before its cap when
    // the geometry retry takes it over.
    const double lowest = *std::min_element(relativeResiduals_.begin(), relativeResiduals_.end());
    std::ostringstream text;
    text << std::setprecision(2) << "the geometric fixed point diverges: after " << updates()
         << " updates the residual at the updated geometry rose from " << lowest << " to "
         << relativeResiduals_.back()
         << " of the step's first residual (a master whose normal turns as it deforms: "
            "Algorithm/Geometry: newton with Algorithm/Geometric Terms: full converges there)";
    return text.str();
  }
  if (const int period = cyclePeriod()) {
    std::ostringstream text;
    text << std::setprecision(4) << "the geometric fixed point cycles: after " << updates()
         << " updates the residual at the updated geometry repeats every " << period
         << " updates (";
    for (auto r = relativeResiduals_.end() - period; r != relativeResiduals_.end(); ++r)
      text << (r == relativeResiduals_.end() - period ? "" : ", ") << *r;
    text << " of the step's first residual): pairings that send the iterate to each other "
            "(with the statuses a fixed point too, where each moves the other, partial Newton "
            "puts the statuses in Newton: Algorithm/Method: partial-newton)";
    return text.str();
  }
  if (relativeResiduals_.size() < kWindow) return message;
  const auto first = relativeResiduals_.end() - kWindow;
  const auto [low, high] = std::minmax_element(first, relativeResiduals_.end());
  if (!(*low > 0) || *high > kStagnation * *low) return message;
  // Stuck well away from a solution instead (the 3D two-body Hertz model pressed by a force
  // under the fixed point: 1.6 to 1.7 of the step's first residual, the statuses and the
  // pairing moving each other): that is no discretization floor, and no Geometry Tolerance
  // should accept it.
  constexpr double kFloorCeiling = 1e-2;
  if (*high >= kFloorCeiling) {
    std::ostringstream hint;
    hint << std::setprecision(2) << "; the residual at the updated geometry stayed at " << *low
         << " to " << *high << " of the step's first residual over the last " << kWindow
         << " updates: the fixed point stalls far from a solution";
    return message + hint.str();
  }
  const double accepting = std::pow(10.0, std::ceil(std::log10(1.5 * *high)));
  std::ostringstream hint;
  hint << std::setprecision(2) << "; the residual at the updated geometry stagnated at " << *low
       << " to " << *high << " of the step's first residual over the last " << kWindow
       << " updates, a floor of the contact discretization above Newton/Geometry Tolerance = "
       << tolerance_
       << " (3D mortar: sliver overlaps that come and go between updates; Newton/Geometry "
          "Tolerance = "
       << accepting << " is above it)";
  return message + hint.str();
}

}  // namespace contactlab
