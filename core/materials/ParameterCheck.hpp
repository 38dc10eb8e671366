#pragma once
// The materials' parameter check: a refused value throws std::invalid_argument as
// "<law>: <what> (got <value>)", so every law names its key and the value in one form.
#include <sstream>
#include <stdexcept>
#include <string>

namespace contactlab {

inline void requireParameter(const char* law, bool ok, const std::string& what, double got) {
  if (ok) return;
  std::ostringstream s;
  s << law << ": " << what << " (got " << got << ")";
  throw std::invalid_argument(s.str());
}

}  // namespace contactlab
