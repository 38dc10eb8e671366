#pragma once
// Rank helpers for the io tests (plain MPI C API, like the writers).
#include <mpi.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace contactlab::test {

inline int commRank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

inline int commSize() {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

// Rank 0 empties `dir`; everyone waits so no rank writes into a folder being removed.
inline void freshDirectory(const std::string& dir) {
  if (commRank() == 0) std::filesystem::remove_all(dir);
  MPI_Barrier(MPI_COMM_WORLD);
}

// Names of the entries of `dir` (empty if it does not exist), sorted.
inline std::vector<std::string> listDirectory(const std::string& dir) {
  std::vector<std::string> names;
  if (!std::filesystem::exists(dir)) return names;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace contactlab::test
