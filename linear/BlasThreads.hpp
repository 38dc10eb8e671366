#pragma once
// How many threads the BLAS runs per MPI rank. MUMPS' factorization spends most of its time in
// the BLAS' dense kernels on its fronts; Debian's threaded OpenBLAS (libopenblas0-pthread) runs
// them on every core, which speeds a one-rank factorization up (doc/performance.md "BLAS
// threads"), but ranks that each start a thread per core oversubscribe the machine. So each
// rank gets the cores of its node shared out among the node's ranks. The BLAS is found at run
// time (dlsym), so a serial or another BLAS is left alone.
#include <mpi.h>

namespace contactlab {

// The cores of a node shared out among its ranks: at least one thread each.
int blasThreadsPerRank(int cores, int ranksOnNode);

// The cores this process may run on (taskset, a batch system's binding, a container's limit
// through its affinity mask), not the machine's; at least 1.
int usableCores();

// The ranks of `comm` that share this process' node (memory). Collective on `comm`.
int ranksOnThisNode(MPI_Comm comm);

// Sets OpenBLAS' thread count for this process to blasThreadsPerRank(the cores this process
// may run on, the ranks of `comm` on this node). Collective on `comm`. A user's
// OPENBLAS_NUM_THREADS or OMP_NUM_THREADS wins: then nothing is set. Returns the BLAS' thread
// count afterwards (1 for a serial BLAS; 0 when the BLAS is not OpenBLAS).
int shareCoresAmongRanks(MPI_Comm comm);

}  // namespace contactlab
