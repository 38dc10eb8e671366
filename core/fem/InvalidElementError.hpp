#pragma once
// Thrown when an element's geometry is unusable at a quadrature point: inverted (det J <= 0) or
// degenerate (det J or dA negligible relative to the element's edge lengths). The geometry
// routines do not know which element they map, so the message starts with "element"; the
// caller names it with withLabel(), e.g.
//   catch (const InvalidElementError& e) {
//     throw e.withLabel("element 42 (gmsh tag 1234) of block 'body'");
//   }
// gives "element 42 (gmsh tag 1234) of block 'body' is inverted: det J = -0.25 at a
// quadrature point".
#include <stdexcept>
#include <string>

namespace contactlab {

class InvalidElementError : public std::runtime_error {
 public:
  enum class Kind { Inverted, Degenerate };

  // `quantity` names the measure that failed: "det J" for cells, "dA" for facets.
  InvalidElementError(Kind kind, const std::string& quantity, double value,
                      const std::string& label = "element");

  Kind kind() const { return kind_; }
  double value() const { return value_; }
  InvalidElementError withLabel(const std::string& label) const;

 private:
  Kind kind_;
  std::string quantity_;
  double value_;
};

}  // namespace contactlab
