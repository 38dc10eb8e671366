#pragma once
// A load time in a message or a file name: 0.625, not 0.625000 (printf's %g).
#include <cstdio>
#include <string>

namespace contactlab {

inline std::string timeText(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", t);
  return buffer;
}

}  // namespace contactlab
