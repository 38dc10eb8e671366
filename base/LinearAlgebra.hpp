#pragma once
// The Tpetra types used by contactlab. Debian's Trilinos 13.2 is instantiated for exactly
// Scalar=double, LO=int, GO=long long, Node=Serial: use nothing else.
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsGraph.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

namespace contactlab {

using Scalar = double;
using LO = int;
using GO = long long;
using Node = Tpetra::Map<>::node_type;
using Map = Tpetra::Map<LO, GO, Node>;
using Graph = Tpetra::CrsGraph<LO, GO, Node>;
using Matrix = Tpetra::CrsMatrix<Scalar, LO, GO, Node>;
using MultiVector = Tpetra::MultiVector<Scalar, LO, GO, Node>;
using Vector = Tpetra::Vector<Scalar, LO, GO, Node>;
using Import = Tpetra::Import<LO, GO, Node>;
using Export = Tpetra::Export<LO, GO, Node>;
using Comm = Teuchos::Comm<int>;

// The MPI communicator under a Teuchos one (MPI_COMM_SELF for a serial Teuchos comm).
inline MPI_Comm rawMpiComm(const Teuchos::RCP<const Comm>& comm) {
  auto mpi = Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(comm);
  return mpi.is_null() ? MPI_COMM_SELF : (*mpi->getRawMpiComm())();
}

}  // namespace contactlab
