#pragma once
// What an error that escapes a command becomes: one sentence on stderr ("contactlab: error:
// ...") and the exit code, 2 for bad input and 1 otherwise. Shared by main() and by
// `contactlab batch`, whose runs must end as a process of their own would.
#include <Teuchos_Comm.hpp>

#include <functional>

namespace contactlab {

// Runs `command` and returns its exit code, or the code of the error that escaped it. Another
// rank may be waiting in a collective call, so a parallel run is aborted as a whole.
int withErrorsReported(const Teuchos::Comm<int>& comm, const std::function<int()>& command);

}  // namespace contactlab
