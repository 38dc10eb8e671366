// The BLAS' threads per rank: the node's cores shared out among its ranks, a user's setting kept.
#include "linear/BlasThreads.hpp"

#include <algorithm>
#include <cstdlib>
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <optional>
#include <string>
#include <thread>

namespace contactlab {
namespace {

TEST(BlasThreads, TheCoresAreSharedOutAmongTheRanksOfANode) {
  EXPECT_EQ(blasThreadsPerRank(2, 1), 2);
  EXPECT_EQ(blasThreadsPerRank(2, 2), 1);
  EXPECT_EQ(blasThreadsPerRank(2, 3), 1);  // oversubscribed: one each, never zero
  EXPECT_EQ(blasThreadsPerRank(8, 3), 2);
  EXPECT_EQ(blasThreadsPerRank(1, 0), 1);
}

// The share's inputs: the tests run on one machine, so every rank is on this node.
TEST(BlasThreads, ItsInputsAreThisProcessCoresAndTheRanksOnItsNode) {
  int ranks = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  EXPECT_EQ(ranksOnThisNode(MPI_COMM_WORLD), ranks);
  EXPECT_GE(usableCores(), 1);
  EXPECT_LE(usableCores(), static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
}

// Sets an environment variable for the scope of a test, and puts back what was there.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value)
      setenv(name, value, 1);
    else
      unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_)
      setenv(name_, old_->c_str(), 1);
    else
      unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

// With Debian's threaded OpenBLAS each rank gets its share of the cores (make test runs with
// OPENBLAS_NUM_THREADS=1, so the test lifts it); with the serial one the count stays 1.
TEST(BlasThreads, EachRankGetsItsShareUnlessTheUserSaidOtherwise) {
  using GetParallel = int (*)();
  const auto parallel = reinterpret_cast<GetParallel>(dlsym(RTLD_DEFAULT, "openblas_get_parallel"));
  if (parallel == nullptr) GTEST_SKIP() << "the BLAS is not OpenBLAS";
  const int ranksOnNode = ranksOnThisNode(MPI_COMM_WORLD);
  const int share = parallel() == 0 ? 1 : blasThreadsPerRank(usableCores(), ranksOnNode);
  {
    // The user's value, read by OpenBLAS when it loaded, stays: contactlab sets nothing.
    ScopedEnv openblas("OPENBLAS_NUM_THREADS", "1");
    using SetThreads = void (*)(int);
    reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))(1);
    EXPECT_EQ(shareCoresAmongRanks(MPI_COMM_WORLD), 1);
  }
  {
    ScopedEnv openblas("OPENBLAS_NUM_THREADS", nullptr), omp("OMP_NUM_THREADS", nullptr);
    EXPECT_EQ(shareCoresAmongRanks(MPI_COMM_WORLD), share);
  }
}

}  // namespace
}  // namespace contactlab
