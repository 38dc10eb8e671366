#pragma once
// An error in what the user gave (scene file, mesh, parameters). Raised before anything is
// written; the command prints its one-sentence message and exits non-zero.
#include <stdexcept>

namespace contactlab {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace contactlab
