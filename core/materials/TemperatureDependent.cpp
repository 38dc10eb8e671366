#include "core/materials/TemperatureDependent.hpp"

#include "base/PiecewiseLinear.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace contactlab {

TemperatureDependent::TemperatureDependent(std::vector<double> temperatures,
                                           std::vector<double> values, const std::string& what)
    : temperatures_(std::move(temperatures)), values_(std::move(values)) {
  if (temperatures_.size() < 2 || temperatures_.size() != values_.size())
    throw std::invalid_argument(what +
                                ": a temperature table needs at least 2 points and as "
                                "many values as Temperatures (got " +
                                std::to_string(values_.size()) + " values for " +
                                std::to_string(temperatures_.size()) + " temperatures)");
  for (std::size_t i = 0; i < temperatures_.size(); ++i)
    if (!std::isfinite(temperatures_[i]) || !std::isfinite(values_[i]) ||
        (i > 0 && !(temperatures_[i] > temperatures_[i - 1])))
      throw std::invalid_argument(what +
                                  ": the Temperatures must be finite and strictly "
                                  "increasing, and the values finite (entry " +
                                  std::to_string(i + 1) + ")");
}

double TemperatureDependent::at(double temperature) const {
  if (temperatures_.empty()) return values_.front();
  return piecewiseLinear(temperatures_, values_, temperature);
}

}  // namespace contactlab
