#pragma once
// Wall seconds since a steady-clock time point: the phase timings (assembly, pairing, linear
// solves) every module reports.
#include <chrono>

namespace contactlab {

inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace contactlab
