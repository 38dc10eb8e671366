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
  if (!changed.empty() && changed == lastChanged_) oneAtATime_ = true;
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
