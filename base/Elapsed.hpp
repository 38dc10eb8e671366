#pragma once
// Wall seconds since a steady-clock time point: the phase timings (assembly, pairing, linear
// solves) every module reports.
#include <chrono>

namespace contactlab {

inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Adds the wall seconds of its scope to *total (nothing when total is null), also when the
// scope is left by an exception: a failed factorization's seconds still count.
class PhaseTimer {
 public:
  explicit PhaseTimer(double* total) : total_(total), start_(std::chrono::steady_clock::now()) {}
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;
  ~PhaseTimer() {
    if (total_) *total_ += secondsSince(start_);
  }

 private:
  double* total_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace contactlab
