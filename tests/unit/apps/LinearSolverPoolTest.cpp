// LinearSolverPool: a run takes back the solver given back under its key, with its counts
// reset; other keys get nothing; the least recently given back is dropped past the capacity.
#include "apps/LinearSolverPool.hpp"

#include <gtest/gtest.h>

namespace contactlab {
namespace {

// A solver that only counts (the pool never calls setMatrix or solve).
class CountingSolver : public LinearSolver {
 public:
  explicit CountingSolver(int id) : id(id) { stats_.factorizations = 3; }
  std::string name() const override { return "counting"; }
  void setMatrix(const Teuchos::RCP<const Matrix>&, bool) override {}
  void solve(const MultiVector&, MultiVector&) override {}
  const int id;
};

int idOf(const std::unique_ptr<LinearSolver>& solver) {
  return dynamic_cast<const CountingSolver&>(*solver).id;
}

TEST(LinearSolverPool, ARunTakesBackTheSolverOfItsKeyWithItsCountsReset) {
  LinearSolverPool pool;
  pool.giveBack("mumps general", std::make_unique<CountingSolver>(1));
  EXPECT_EQ(pool.take("mumps symmetric"), nullptr);
  auto solver = pool.take("mumps general");
  ASSERT_NE(solver, nullptr);
  EXPECT_EQ(idOf(solver), 1);
  EXPECT_EQ(solver->stats().factorizations, 0);
  EXPECT_EQ(pool.take("mumps general"), nullptr);  // taken: no longer kept
  EXPECT_EQ(pool.size(), 0u);
}

TEST(LinearSolverPool, TheLeastRecentlyGivenBackIsDroppedPastTheCapacity) {
  LinearSolverPool pool(2);
  pool.giveBack("a", std::make_unique<CountingSolver>(1));
  pool.giveBack("b", std::make_unique<CountingSolver>(2));
  pool.giveBack("a", std::make_unique<CountingSolver>(3));  // replaces a's, now the newest
  pool.giveBack("c", std::make_unique<CountingSolver>(4));  // b is the oldest: dropped
  EXPECT_EQ(pool.size(), 2u);
  EXPECT_EQ(pool.take("b"), nullptr);
  EXPECT_EQ(idOf(pool.take("a")), 3);
  EXPECT_EQ(idOf(pool.take("c")), 4);
}

TEST(LinearSolverPool, NothingIsKeptAtCapacityZeroNorForANullSolver) {
  LinearSolverPool none(0);
  none.giveBack("a", std::make_unique<CountingSolver>(1));
  EXPECT_EQ(none.size(), 0u);
  LinearSolverPool pool;
  pool.giveBack("a", nullptr);
  EXPECT_EQ(pool.size(), 0u);
}

}  // namespace
}  // namespace contactlab
