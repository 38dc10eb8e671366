#pragma once
// MumpsSolver's state: private to linear/MumpsSolver*.cpp (it keeps dmumps_c.h and mpi.h out of
// MumpsSolver.hpp). MumpsSolver.cpp factorizes and solves, MumpsSolverReuse.cpp answers a
// matrix from the last factorization (CapacitanceCorrection).
#include "linear/CapacitanceCorrection.hpp"
#include "linear/MatrixSnapshot.hpp"
#include "linear/MumpsErrors.hpp"
#include "linear/MumpsSolver.hpp"

#include <Teuchos_Comm.hpp>
#include <dmumps_c.h>
#include <mpi.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace contactlab {

struct MumpsSolver::Impl {
  DMUMPS_STRUC_C id{};
  MPI_Comm comm = MPI_COMM_NULL;  // a duplicate, so MUMPS' messages never meet Tpetra's
  Teuchos::RCP<const Comm> teuchosComm;
  bool initialized = false;
  bool analysed = false;
  bool factored = false;
  Teuchos::RCP<const Matrix> A;
  // Distributed assembled input (1-based global indices); must outlive the factorization
  // because the error analysis of a solve reads A again.
  std::vector<MUMPS_INT> irn, jcn;
  std::vector<double> values;
  // Right-hand side and solution are centralized on rank 0.
  Teuchos::RCP<const Map> rootMap;
  Teuchos::RCP<const Import> toRoot, fromRoot;
  Teuchos::RCP<const Map> rangeMap, domainMap;  // those the importers were built for
  std::optional<ErrorAnalysis> lastErrorAnalysis;
  // Factorization reuse: the matrix last factorized (the reference A0), what its factorization
  // cost, and the correction of a later matrix A that solves go through while `correcting`.
  MatrixSnapshot reference;
  double referenceFlops = 0;          // RINFOG(3): flops of the reference's elimination
  double referenceEntries = 0;        // INFOG(29): entries in its factors
  std::vector<GO> correctionIndices;  // sorted: indices whose entries of A0^-1 are known
  std::unique_ptr<CapacitanceCorrection> correction;  // on the host only
  bool correcting = false;
  Teuchos::RCP<const Matrix> current;  // the matrix solves are for
  double currentNormInf = 0;           // ||A||_inf of `current` while correcting

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  // Also runs when the constructor throws after MUMPS' initialization.
  ~Impl() {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (finalized) return;  // too late to free anything collectively
    if (initialized) run(-2);
    if (comm != MPI_COMM_NULL) MPI_Comm_free(&comm);
  }

  MUMPS_INT& icntl(int i) { return id.icntl[i - 1]; }
  MUMPS_INT infog(int i) const { return id.infog[i - 1]; }
  double rinfog(int i) const { return id.rinfog[i - 1]; }
  bool isRoot() const { return teuchosComm->getRank() == 0; }

  void run(int job) {
    id.job = job;
    dmumps_c(&id);
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

}  // namespace contactlab
