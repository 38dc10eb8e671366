#pragma once
// An error found on some ranks must stop every rank, or the others wait forever in the next
// collective call. agreeOnError is collective: when any rank passes a non-empty message, every
// rank throws InputError with the message of the lowest such rank.
#include "base/LinearAlgebra.hpp"

#include <string>

namespace contactlab {

void agreeOnError(const Comm& comm, const std::string& localMessage);

// Runs `work`, then agrees: any exception on any rank (gmsh's strings included) is rethrown as
// InputError on all.
template <class Work>
void collectively(const Comm& comm, Work&& work) {
  std::string message;
  try {
    work();
  } catch (const std::exception& e) {
    message = e.what();
    if (message.empty()) message = "unknown error";
  } catch (const std::string& e) {  // gmsh throws strings
    message = "gmsh: " + e;
  } catch (...) {
    message = "unknown error";
  }
  agreeOnError(comm, message);
}

}  // namespace contactlab
