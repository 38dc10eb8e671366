#include "core/fem/InvalidElementError.hpp"

#include <sstream>

namespace contactlab {
namespace {

std::string message(InvalidElementError::Kind kind, const std::string& quantity, double value,
                    const std::string& label) {
  std::ostringstream s;
  s << label << " is " << (kind == InvalidElementError::Kind::Inverted ? "inverted" : "degenerate")
    << ": " << quantity << " = " << value << " at a quadrature point";
  return s.str();
}

}  // namespace

InvalidElementError::InvalidElementError(Kind kind, const std::string& quantity, double value,
                                         const std::string& label)
    : std::runtime_error(message(kind, quantity, value, label)),
      kind_(kind),
      quantity_(quantity),
      value_(value) {}

InvalidElementError InvalidElementError::withLabel(const std::string& label) const {
  return InvalidElementError(kind_, quantity_, value_, label);
}

}  // namespace contactlab
