#pragma once
// Thrown by an element kernel when the current iterate cannot be evaluated: the material failed
// (a local return map that does not converge, J <= 0 in a hyperelastic law) or u turns the
// element inside out (det F <= 0). Not an input error: the step fails with `code()` as its
// named failure and step cutting takes over. The kernel does not know which element it
// evaluates; the caller prefixes the element's identity.
#include <stdexcept>
#include <string>

namespace contactlab {

class ElementUpdateError : public std::runtime_error {
 public:
  // code: "material-update-failed" or "inverted-element".
  ElementUpdateError(std::string code, int point, const std::string& what)
      : std::runtime_error(what), code_(std::move(code)), point_(point) {}
  const std::string& code() const { return code_; }
  int point() const { return point_; }

 private:
  std::string code_;
  int point_;
};

}  // namespace contactlab
