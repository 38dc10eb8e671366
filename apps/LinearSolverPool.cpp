#include "apps/LinearSolverPool.hpp"

namespace contactlab {

std::unique_ptr<LinearSolver> LinearSolverPool::take(const std::string& key) {
  for (auto it = kept_.begin(); it != kept_.end(); ++it) {
    if (it->first != key) continue;
    std::unique_ptr<LinearSolver> solver = std::move(it->second);
    kept_.erase(it);
    solver->resetStats();
    return solver;
  }
  return nullptr;
}

void LinearSolverPool::giveBack(const std::string& key, std::unique_ptr<LinearSolver> solver) {
  if (!solver || capacity_ == 0) return;
  for (auto it = kept_.begin(); it != kept_.end(); ++it)
    if (it->first == key) {
      kept_.erase(it);
      break;
    }
  kept_.emplace_front(key, std::move(solver));
  while (kept_.size() > capacity_)
    kept_.pop_back();
}

}  // namespace contactlab
