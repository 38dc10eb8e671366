// Ifpack2 preconditioners (see Preconditioners.hpp).
#include "linear/LinearSolver.hpp"
#include "linear/Preconditioners.hpp"

#include <Ifpack2_Factory.hpp>
#include <Teuchos_ParameterList.hpp>

namespace contactlab {

Teuchos::RCP<Operator> createIfpack2Preconditioner(const Teuchos::RCP<const Matrix>& A,
                                                   const PreconditionerOptions& options) {
  using Kind = PreconditionerOptions::Kind;
  using RowMatrix = Tpetra::RowMatrix<Scalar, LO, GO, Node>;
  Teuchos::ParameterList params;
  std::string type;
  if (options.kind == Kind::ifpack2Sgs) {
    type = "RELAXATION";
    params.set("relaxation: type", "Symmetric Gauss-Seidel");
    params.set("relaxation: sweeps", options.sweeps);
    params.set("relaxation: damping factor", options.damping);
  } else if (options.kind == Kind::ifpack2Riluk || options.kind == Kind::ifpack2Ilut) {
    // Incomplete factorizations are local: additive Schwarz makes them one preconditioner.
    type = "SCHWARZ";
    Teuchos::ParameterList inner;
    if (options.kind == Kind::ifpack2Riluk) {
      params.set("inner preconditioner name", "RILUK");
      inner.set("fact: iluk level-of-fill", options.fillLevel);
    } else {
      params.set("inner preconditioner name", "ILUT");
      inner.set("fact: ilut level-of-fill", options.fillRatio);
      inner.set("fact: drop tolerance", options.dropTolerance);
    }
    params.set("inner preconditioner parameters", inner);
    params.set("schwarz: overlap level", options.overlap);
    // The default ZERO is not symmetric, and CG then fails (doc/architecture.md "Trilinos and
    // Debian").
    params.set("schwarz: combine mode", options.symmetric ? "ADD" : "ZERO");
    params.set("schwarz: use reordering", false);
  } else {
    throw LinearSolverError("createIfpack2Preconditioner called for a non-Ifpack2 kind");
  }
  Teuchos::RCP<const RowMatrix> rowMatrix = A;
  auto prec = Ifpack2::Factory::create<RowMatrix>(type, rowMatrix);
  prec->setParameters(params);
  prec->initialize();
  prec->compute();
  return prec;
}

}  // namespace contactlab
