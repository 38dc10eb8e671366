#pragma once
// MUMPS' error codes (INFOG(1) < 0) in words, for LinearSolverError messages.
#include <string>

namespace contactlab {

// -8, -9, -17, -20: a workspace sized from ICNTL(14) was too small; raising it may help.
bool isWorkspaceTooSmall(int code);

// The meaning of the common INFOG(1) codes (MUMPS 5.5 user guide, section 8); info2 is INFOG(2).
std::string mumpsErrorMeaning(int code, int info2);

}  // namespace contactlab
