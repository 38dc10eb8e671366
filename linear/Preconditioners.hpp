#pragma once
// Preconditioners of BelosSolver, each built in its own translation unit so that only that file
// pays for Ifpack2's or MueLu's headers (MueLu's are heavy to compile).
#include "base/LinearAlgebra.hpp"

#include <Teuchos_RCP.hpp>
#include <Tpetra_Operator.hpp>

namespace contactlab {

using Operator = Tpetra::Operator<Scalar, LO, GO, Node>;

struct PreconditionerOptions {
  enum class Kind { none, ifpack2Sgs, ifpack2Riluk, ifpack2Ilut, muelu };
  Kind kind = Kind::none;
  // The Krylov method is CG: additive Schwarz sums overlaps (combine mode ADD), which keeps the
  // preconditioner symmetric; otherwise overlaps are dropped (restricted Schwarz, ZERO).
  bool symmetric = true;
  int sweeps = 1;               // Gauss-Seidel sweeps (ifpack2-sgs, MueLu smoother)
  double damping = 1.0;         // Gauss-Seidel damping factor
  int fillLevel = 1;            // RILUK level of fill
  double fillRatio = 2.0;       // ILUT: kept entries per row relative to A's (>= 1)
  double dropTolerance = 1e-4;  // ILUT: drops entries below this relative magnitude
  int overlap = 1;              // additive Schwarz overlap (ILU variants)
  int blockSize = 1;            // MueLu: unknowns per node (3 for 3D elasticity)
  int maxLevels = 10;           // MueLu
  int coarseMaxSize = 1000;     // MueLu: stop coarsening below this many unknowns
  int coarseSweeps = 4;         // MueLu: Gauss-Seidel sweeps of the coarse "solve"
};

// Ifpack2 preconditioner of A, initialized and computed (Ifpack2Preconditioner.cpp).
Teuchos::RCP<Operator> createIfpack2Preconditioner(const Teuchos::RCP<const Matrix>& A,
                                                   const PreconditionerOptions& options);

// Smoothed-aggregation MueLu hierarchy of A (MueLuPreconditioner.cpp). The coarse level is
// relaxed, never solved by KLU2 (MueLu's default), which is wrong on more than one rank here.
// nullSpace (may be null) is the near-null space on A's row map, e.g. rigid-body modes.
Teuchos::RCP<Operator> createMueLuPreconditioner(const Teuchos::RCP<const Matrix>& A,
                                                 const Teuchos::RCP<const MultiVector>& nullSpace,
                                                 const PreconditionerOptions& options);

}  // namespace contactlab
