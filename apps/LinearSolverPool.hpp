#pragma once
// The linear solvers a process keeps from one run to the next (`contactlab batch`, the study
// runner's shared process). A run takes the solver built with its own Linear Solver settings
// back from the pool, with whatever that solver holds: MUMPS its symbolic analysis, the last
// factors and the entries of their inverse already computed. A study's runs on one mesh differ
// only in the contact terms, so a run after the first is answered by low-rank corrections of
// the last run's factors (MumpsSolverReuse.cpp), each solve checked by the new matrix's own
// residual: the same results to the solver's tolerance, without the factorization.
#include "linear/LinearSolver.hpp"

#include <list>
#include <memory>
#include <string>
#include <utility>

namespace contactlab {

class LinearSolverPool {
 public:
  // At most `capacity` solvers are kept (the least recently given back is dropped first): each
  // may hold the factors of a model, so a study that alternates between meshes does not keep
  // every one.
  explicit LinearSolverPool(std::size_t capacity = 2) : capacity_(capacity) {}

  // The solver given back under `key` (the solver's settings; see keyOf), or null. Its counts
  // (stats()) are reset: they count the taking run's work.
  std::unique_ptr<LinearSolver> take(const std::string& key);
  // Keeps `solver` for a later take(key).
  void giveBack(const std::string& key, std::unique_ptr<LinearSolver> solver);
  std::size_t size() const { return kept_.size(); }

 private:
  std::size_t capacity_;
  std::list<std::pair<std::string, std::unique_ptr<LinearSolver>>> kept_;  // newest first
};

}  // namespace contactlab
