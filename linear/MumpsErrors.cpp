#include "linear/MumpsErrors.hpp"

namespace contactlab {

bool isWorkspaceTooSmall(int code) {
  return code == -8 || code == -9 || code == -17 || code == -20;
}

// The meaning of the common INFOG(1) codes (MUMPS 5.5 user guide, section 8).
std::string mumpsErrorMeaning(int code, int info2) {
  switch (code) {
    case -1:
      return "an error occurred on rank " + std::to_string(info2);
    case -2:
      return "the number of nonzeros is out of range (" + std::to_string(info2) + ")";
    case -3:
      return "MUMPS was called with an invalid JOB (e.g. a solve without factorization)";
    case -5:
    case -7:
      return "not enough memory during analysis";
    case -6:
      return "matrix is structurally singular (structural rank " + std::to_string(info2) + ")";
    case -8:
    case -9:
    case -17:
    case -20:
      return "MUMPS' internal workspace is too small (raise Memory Relaxation, ICNTL(14))";
    case -10:
      return "matrix is numerically singular";
    case -11:
    case -12:
    case -14:
    case -15:
      return "MUMPS' internal workspace is too small for the solve";
    case -13:
      return "memory allocation failed (" +
             (info2 < 0 ? std::to_string(-static_cast<long long>(info2)) + " million"
                        : std::to_string(info2)) +
             " entries requested)";
    case -16:
      return "the matrix order N is out of range";
    case -22:
      return "an input array is missing or too small";
    case -38:
      return "the parallel ordering is not available";
    case -40:
      return "matrix was declared symmetric positive definite but a negative or zero pivot was "
             "met (use Mode symmetric-indefinite)";
    default:
      return "see the MUMPS user guide";
  }
}

}  // namespace contactlab
