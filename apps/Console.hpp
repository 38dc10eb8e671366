#pragma once
// What `run`, `validate` and `critical-mu` print besides their progress lines (RunProgress),
// in one place that honours --quiet. Rank 0 prints; the other ranks print nothing.
// - info: what the run is doing or chose (the model's size, coefficients left to contactlab,
//   an earlier run's files removed, the uniqueness check's details), on stderr; --quiet drops
//   it (the same facts are in summary.json).
// - warning: a result to distrust or a poor choice, on stderr, always.
// - result: the command's answer (the closing line and where the results are, validate's
//   verdict, critical-mu's), on stdout, always.
// Errors are the exceptions' (CommandErrors, reportInputError), always.
#include <iostream>
#include <string>

namespace contactlab {

class Console {
 public:
  Console(bool quiet, bool root) : quiet_(quiet), root_(root) {}

  void info(const std::string& line) const {
    if (root_ && !quiet_) std::cerr << "contactlab: " << line << "\n";
  }
  void warning(const std::string& line) const {
    if (root_) std::cerr << "contactlab: warning: " << line << "\n";
  }
  // Printed as it is (a result may be indented under the line before it).
  void result(const std::string& line) const {
    if (root_) std::cout << line << "\n";
  }

  bool quiet() const { return quiet_; }

 private:
  bool quiet_, root_;
};

}  // namespace contactlab
