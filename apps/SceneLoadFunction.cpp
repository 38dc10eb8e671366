#include "apps/SceneLoadFunction.hpp"

#include "base/InputError.hpp"

#include <cmath>

namespace contactlab {

using Teuchos::ParameterList;

LoadFunction loadFunction(const ParameterList& p, double endTime, const std::string& where,
                          const std::string& path) {
  LoadFunction f;
  const std::string kind = p.get<std::string>("Function");
  f.kind = kind == "constant" ? LoadFunction::Kind::Constant
           : kind == "table"  ? LoadFunction::Kind::Table
                              : LoadFunction::Kind::Ramp;
  const double stop = p.get<double>("Stop Time");
  f.endTime = stop > 0 ? stop : endTime;
  f.startTime = p.get<double>("Start Time");
  if (!(stop >= 0 && stop <= endTime))
    throw InputError(where + ": " + path + "/Stop Time must be in [0, End Time] (0: End Time)");
  if (!(f.startTime >= 0 && f.startTime < f.endTime))
    throw InputError(where + ": " + path + "/Start Time must be in [0, Stop Time)");
  const auto& times = p.get<Teuchos::Array<double>>("Times");
  const auto& factors = p.get<Teuchos::Array<double>>("Factors");
  if (f.kind != LoadFunction::Kind::Table) {
    if (!times.empty() || !factors.empty())
      throw InputError(where + ": " + path + "/Times and Factors belong to Function: table; " +
                       "remove them or set Function: table");
    return f;
  }
  if (times.size() < 2 || times.size() != factors.size())
    throw InputError(where + ": " + path + "/Function table needs Times and Factors of the " +
                     "same length, at least 2 (got " + std::to_string(times.size()) + " and " +
                     std::to_string(factors.size()) + ")");
  for (Teuchos::Array<double>::size_type i = 0; i < times.size(); ++i) {
    if (!std::isfinite(times[i]) || !std::isfinite(factors[i]) ||
        (i > 0 && !(times[i] > times[i - 1])))
      throw InputError(where + ": " + path + "/Times must be finite and strictly increasing, " +
                       "and Factors finite (entry " + std::to_string(i + 1) + ")");
  }
  f.times.assign(times.begin(), times.end());
  f.factors.assign(factors.begin(), factors.end());
  return f;
}

}  // namespace contactlab
