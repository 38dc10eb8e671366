#pragma once
// A number in a message or a file name: printf's %g (6 significant digits: 0.625, not
// 0.625000), or fewer when asked. One definition for every module: two modules' functions of
// the same name and signature with different formats would silently replace one another at
// link time.
#include <cstdio>
#include <string>

namespace contactlab {

inline std::string numberText(double value, int significantDigits = 6) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", significantDigits, value);
  return buffer;
}

// A residual or a size in a message: printf's %.3e (1.234e-05), the solver's progress format.
inline std::string scientificText(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.3e", value);
  return buffer;
}

}  // namespace contactlab
