#pragma once
// Gathering per-rank pieces on rank 0 (checkpoints, whole fields for the Python module).
#include <mpi.h>

#include <numeric>
#include <vector>

namespace contactlab {

// The concatenation of every rank's `local` on rank 0 (in rank order), empty elsewhere.
template <class T>
std::vector<T> gatherOnRoot(const std::vector<T>& local, MPI_Datatype type, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const int count = static_cast<int>(local.size());
  std::vector<int> counts(size), starts(size);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  std::vector<T> all;
  if (rank == 0) {
    std::partial_sum(counts.begin(), counts.end() - 1, starts.begin() + 1);
    all.resize(static_cast<std::size_t>(starts.back()) + counts.back());
  }
  MPI_Gatherv(local.data(), count, type, all.data(), counts.data(), starts.data(), type, 0, comm);
  return all;
}

}  // namespace contactlab
