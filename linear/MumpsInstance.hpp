#pragma once
// One MUMPS instance in double (DMUMPS) or single (SMUMPS) precision: its C structure and the
// calls MumpsSolver makes on it, written once for both precisions. Private to
// linear/MumpsSolver*.cpp (it includes the MUMPS C headers and mpi.h).
#include "linear/LinearSolver.hpp"
#include "linear/MumpsErrors.hpp"

#include <dmumps_c.h>
#include <mpi.h>

#include <smumps_c.h>
#include <string>

namespace contactlab {

template <class Struct>
struct MumpsEntryPoint;
template <>
struct MumpsEntryPoint<DMUMPS_STRUC_C> {
  using Real = double;
  static void call(DMUMPS_STRUC_C* id) { dmumps_c(id); }
};
template <>
struct MumpsEntryPoint<SMUMPS_STRUC_C> {
  using Real = float;
  static void call(SMUMPS_STRUC_C* id) { smumps_c(id); }
};

// ICNTL(14) is raised this way after a workspace-too-small error, then the factorization is
// retried once. Generous, because a second failure costs a whole factorization: matrices with
// many delayed pivots can need 100-200 %.
inline int raisedRelaxation(int percent) {
  return percent + 200 > 4 * percent ? percent + 200 : 4 * percent;
}

template <class Struct>
struct MumpsInstance {
  using Real = typename MumpsEntryPoint<Struct>::Real;
  Struct id{};
  bool initialized = false;
  bool analysed = false;  // the pattern MumpsSolver holds (Impl::irn, jcn) is analysed
  bool factored = false;  // and factorized

  MumpsInstance() = default;
  MumpsInstance(const MumpsInstance&) = delete;
  MumpsInstance& operator=(const MumpsInstance&) = delete;
  ~MumpsInstance() { finalize(); }
  // JOB = -2 (collective); too late once MPI is finalized.
  void finalize() {
    int mpiFinalized = 0;
    MPI_Finalized(&mpiFinalized);
    if (initialized && !mpiFinalized) run(-2);
    initialized = analysed = factored = false;
  }

  MUMPS_INT& icntl(int i) { return id.icntl[i - 1]; }
  MUMPS_INT icntl(int i) const { return id.icntl[i - 1]; }
  MUMPS_INT infog(int i) const { return id.infog[i - 1]; }
  double rinfog(int i) const { return id.rinfog[i - 1]; }
  // Entries in the factors after a factorization (INFOG(29); negative: -INFOG(29) million,
  // past 32 bits).
  double factorEntries() const { return infog(29) >= 0 ? infog(29) : -1e6 * infog(29); }
  void run(int job) {
    id.job = job;
    MumpsEntryPoint<Struct>::call(&id);
  }

  // JOB = -1 on `comm` (every rank works: PAR = 1), then the controls MumpsSolver uses.
  void initialize(MPI_Comm comm, int sym, int memoryRelaxation, bool determinant) {
    id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(comm));
    id.par = 1;
    id.sym = static_cast<MUMPS_INT>(sym);
    run(-1);
    initialized = true;
    check("initialization");
    // Silence MUMPS: errors, diagnostics, statistics, verbosity (ICNTL(1..4)).
    icntl(1) = -1;
    icntl(2) = -1;
    icntl(3) = -1;
    icntl(4) = 0;
    icntl(5) = 0;   // assembled input
    icntl(18) = 3;  // distributed assembled input: each rank passes its rows
    icntl(20) = 0;  // dense right-hand side ...
    icntl(21) = 0;  // ... and solution, centralized on the host
    // ICNTL(7), the ordering, is set before each analysis: it depends on the size.
    // Sequential analysis. The parallel one fails with PORD only (INFOG(1) = -38); with
    // PT-SCOTCH (ICNTL(29) = 1) it runs, but does not pay (the analysis is done once per
    // pattern; doc/performance.md "Fill-reducing ordering: SCOTCH").
    icntl(28) = 1;
    icntl(14) = memoryRelaxation;
    icntl(33) = determinant ? 1 : 0;
    icntl(11) = 0;
  }

  // JOB = 2 with the values `a_loc` points to; ICNTL(14) raised once if the workspace was too
  // small. Throws on failure (SingularMatrixError for a zero pivot with pivoting).
  void factorize() {
    factored = false;
    run(2);
    if (isWorkspaceTooSmall(infog(1))) {
      icntl(14) = raisedRelaxation(icntl(14));
      run(2);
      if (isWorkspaceTooSmall(infog(1)))
        throw LinearSolverError(
            "MUMPS factorization failed: internal workspace too small even with Memory "
            "Relaxation raised to " +
            std::to_string(icntl(14)) + " % (INFOG(1) = " + std::to_string(infog(1)) +
            "); raise Memory Relaxation");
    }
    check("factorization");
    factored = true;
  }

  void check(const char* phase) const {
    const int code = infog(1);
    if (code >= 0) return;
    // SYM = 1 does not pivot: a zero pivot may only mean the matrix is not positive definite.
    const std::string hint = id.sym == 1 && code == -10
                                 ? "; in Mode symmetric this may only mean that the matrix is "
                                   "not positive definite: try Mode symmetric-indefinite"
                                 : "";
    const std::string message = std::string("MUMPS ") + phase +
                                " failed: " + mumpsErrorMeaning(code, infog(2)) +
                                " (INFOG(1) = " + std::to_string(code) + ")" + hint;
    // With pivoting (SYM = 0, 2) a zero pivot is a singular matrix; without, it is ambiguous.
    if (code == -10 && id.sym != 1) throw SingularMatrixError(message);
    throw LinearSolverError(message);
  }
};

using DoubleMumps = MumpsInstance<DMUMPS_STRUC_C>;
using SingleMumps = MumpsInstance<SMUMPS_STRUC_C>;

}  // namespace contactlab
