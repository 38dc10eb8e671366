#include "algorithms/StatusLoop.hpp"

#include <algorithm>

namespace contactlab {

bool StatusLoop::update(const Vector& x, double t) {
  std::vector<StatusChange> changes = controls_.statusUpdate(x, t);
  // A point whose status the cycling treatment forces does not hold the fixed point up: its
  // frozen status follows the law, for when the forcing is released.
  std::vector<std::size_t> changed;
  for (const StatusChange& change : changes)
    if (!change.forced) changed.push_back(change.point);
  // All of them at once sends the iterate back to where the last update came from. One at a
  // time is the single-exchange rule of active-set methods for complementarity problems: from
  // each state the most violated status is put right, and the others are judged again.
  const bool reversed = !changed.empty() && changed == lastChanged_;
  if (reversed) oneAtATime_ = true;
  // A reversal that opens the points the iterate holds closed in tension says their frozen
  // friction thresholds are stale: read there, where every other point holds, the thresholds
  // give those points none (a threshold update from the iterate with them open and
  // penetrating makes the other points carry their load, and cycled at r_n >= 1e2 E/h).
  thresholdsStale_ =
      reversed && std::all_of(changes.begin(), changes.end(),
                              [](const StatusChange& c) { return c.forced || c.status == 0; });
  if (oneAtATime_ && changed.size() > 1) {
    const auto largest = std::max_element(
        changes.begin(), changes.end(), [](const StatusChange& a, const StatusChange& b) {
          return a.forced != b.forced ? a.forced : a.violation < b.violation;
        });
    const StatusChange kept = *largest;
    changes.erase(
        std::remove_if(changes.begin(), changes.end(),
                       [&](const StatusChange& c) { return !c.forced && c.point != kept.point; }),
        changes.end());
    changed = {kept.point};
  }
  controls_.applyStatuses(changes);
  lastChanged_ = changed;
  return !changed.empty();
}

}  // namespace contactlab
