#pragma once
// A function of one variable tabulated at strictly increasing abscissae: linear between them,
// held at the first and last values beyond them. One copy for every table of the project: a
// load's factor in time (core/problem/Loads.hpp, LoadFunction) and a material parameter in
// temperature (core/materials/TemperatureDependent.hpp), two modules of core that share no
// other header.
#include <cstddef>
#include <vector>

namespace contactlab {

// xs strictly increasing, ys of the same size, at least one point (the caller checks).
inline double piecewiseLinear(const std::vector<double>& xs, const std::vector<double>& ys,
                              double x) {
  if (x <= xs.front()) return ys.front();
  if (x >= xs.back()) return ys.back();
  std::size_t i = 1;
  while (xs[i] < x)
    ++i;
  const double w = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
  return (1 - w) * ys[i - 1] + w * ys[i];
}

}  // namespace contactlab
