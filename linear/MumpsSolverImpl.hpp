#pragma once
// MumpsSolver's state: private to linear/MumpsSolver*.cpp (it keeps the MUMPS headers and mpi.h
// out of MumpsSolver.hpp). MumpsSolver.cpp factorizes and solves, MumpsSolverReuse.cpp answers a
// matrix from the last factorization (CapacitanceCorrection), MumpsSolverPrecision.cpp factorizes
// in single precision and refines the solves in double.
#include "linear/CapacitanceCorrection.hpp"
#include "linear/MatrixSnapshot.hpp"
#include "linear/MumpsInstance.hpp"
#include "linear/MumpsSolver.hpp"

#include <Teuchos_Comm.hpp>
#include <mpi.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace contactlab {

struct MumpsSolver::Impl {
  // The double-precision instance always exists; the single-precision one is created when a
  // matrix is first factorized in single precision (MumpsSolverPrecision.cpp). Each keeps its own
  // analysis of the pattern below; `singleFactors` says whose factors the solves use.
  DoubleMumps dbl;
  std::unique_ptr<SingleMumps> sgl;
  bool singleFactors = false;
  // Single precision is decided at the first analysis (Precision: automatic) and dropped for
  // good after a matrix whose single factors failed (a refinement that did not converge, a
  // pivot that vanished in single precision).
  std::optional<bool> singleChosen;
  MPI_Comm comm = MPI_COMM_NULL;  // a duplicate, so MUMPS' messages never meet Tpetra's
  Teuchos::RCP<const Comm> teuchosComm;
  bool factored = false;  // the active instance holds the factors of `A`
  Teuchos::RCP<const Matrix> A;
  // Distributed assembled input (1-based global indices); must outlive the factorization
  // because the error analysis of a solve reads A again.
  std::vector<MUMPS_INT> irn, jcn;
  std::vector<double> values;
  std::vector<float> singleValues;  // `values` rounded, for the single-precision instance
  MUMPS_INT ordering = 0;           // ICNTL(7) for the analyses of this pattern
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
  double currentNormInf = 0;           // ||A||_inf of `current` when its solves are refined

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  // Also runs when the constructor throws after MUMPS' initialization; the instances (members)
  // are freed before the communicator they use.
  ~Impl() {
    sgl.reset();
    dbl.finalize();
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (comm != MPI_COMM_NULL && !finalized) MPI_Comm_free(&comm);
  }

  bool isRoot() const { return teuchosComm->getRank() == 0; }
  // The instance whose factors the solves use: f(dbl) or f(*sgl).
  template <class F>
  auto withFactors(F&& f) {
    return singleFactors ? f(*sgl) : f(dbl);
  }
  template <class F>
  auto withFactors(F&& f) const {
    return singleFactors ? f(static_cast<const SingleMumps&>(*sgl)) : f(dbl);
  }
};

}  // namespace contactlab
