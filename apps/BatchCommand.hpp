#pragma once
// `contactlab batch`: runs scenes one after another in this process, as the study runner asks
// (apps/study/study.py), so that the process's start-up is paid once and a linear solver
// carries over from one run to the next (LinearSolverPool: on one mesh, a later run's
// matrices are corrections of the last factors, not factorizations).
//
// Input, one run a line on stdin, fields separated by tabs:
//   OUT <tab> SCENE [<tab> key/path=value ...]
// (SCENE empty: the built-in scene; the values as `contactlab run --set` takes them). The run's
// stdout and stderr go to OUT/run.log; when it ends, one line "exit CODE" on stdout, CODE being
// what `contactlab run --out OUT SCENE --set ...` would have exited with. End of input ends
// the batch (exit 0); a run stopped by SIGINT or SIGTERM ends it with that run's code.
#include "base/LinearAlgebra.hpp"

namespace contactlab {

// One rank only (the study runner's processes are single-rank): refused on more.
int batchCommand(const Teuchos::RCP<const Comm>& comm, bool quiet);

}  // namespace contactlab
