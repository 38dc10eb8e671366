// gtest main shared by every test binary: MPI and Kokkos through Tpetra's scope guard, and
// gtest's output printed by rank 0 only.
#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  if (Tpetra::getDefaultComm()->getRank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  return RUN_ALL_TESTS();
}
