#pragma once
// A material parameter as a function of the temperature T: a constant, or piecewise linear
// through tabulated points (T_i, v_i) and held at the first and last values beyond them (a data
// sheet gives a property between its end temperatures, and a model heated a little past them
// should not extrapolate a slope it was never given).
#include <string>
#include <vector>

namespace contactlab {

class TemperatureDependent {
 public:
  // A constant: the same value at every temperature. Implicit, so that a law's parameter
  // struct still takes `E = 205000.0`.
  TemperatureDependent(double constant = 0.0) : values_{constant} {}  // NOLINT: implicit
  // A table. Throws std::invalid_argument, naming `what`, unless there are at least 2 points,
  // as many values as temperatures, all finite, the temperatures strictly increasing.
  TemperatureDependent(std::vector<double> temperatures, std::vector<double> values,
                       const std::string& what);

  double at(double temperature) const;
  bool isConstant() const { return temperatures_.empty(); }
  // The constant, or the tabulated values: a piecewise linear function takes its extremes at
  // them, so a range check of these is a check at every temperature.
  const std::vector<double>& values() const { return values_; }
  const std::vector<double>& temperatures() const { return temperatures_; }

 private:
  std::vector<double> temperatures_;  // empty: a constant, values_ = {it}
  std::vector<double> values_;
};

}  // namespace contactlab
