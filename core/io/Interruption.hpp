#pragma once
// SIGINT and SIGTERM end a run cleanly: the handler only records the signal, the load-step loop
// sees it at its next Newton iterate (every rank at the same iterate: see
// interruptionAgreed), the file being written is finished, summary.json says
// `failure: interrupted`, and the process exits 128 + signal. A second signal kills at once.
#include <mpi.h>

namespace contactlab {

void installInterruptionHandlers();
// Collective over `comm`: the largest signal any rank received (0 if none), so that every
// rank stops at the same iterate.
int interruptionAgreed(MPI_Comm comm);

}  // namespace contactlab
