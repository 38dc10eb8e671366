#include "core/io/Interruption.hpp"

#include <csignal>

namespace contactlab {
namespace {

volatile std::sig_atomic_t received = 0;

extern "C" void onSignal(int signal) {
  if (received != 0) {  // the second one: the user means it
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  received = signal;
}

}  // namespace

void installInterruptionHandlers() {
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
}

int interruptionAgreed(MPI_Comm comm) {
  int local = received, global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, comm);
  return global;
}

}  // namespace contactlab
