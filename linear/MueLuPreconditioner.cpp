// MueLu smoothed aggregation (see Preconditioners.hpp). The only file that includes MueLu.
#include "linear/Preconditioners.hpp"

#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <Teuchos_ParameterList.hpp>

namespace contactlab {

Teuchos::RCP<Operator> createMueLuPreconditioner(const Teuchos::RCP<const Matrix>& A,
                                                 const Teuchos::RCP<const MultiVector>& nullSpace,
                                                 const PreconditionerOptions& options) {
  Teuchos::ParameterList params;
  params.set("verbosity", "none");
  params.set("multigrid algorithm", "sa");
  params.set("problem: symmetric", options.symmetric);
  params.set("number of equations", options.blockSize);
  params.set("max levels", options.maxLevels);
  params.set("coarse: max size", options.coarseMaxSize);
  params.set("repartition: enable", false);  // needs Zoltan2 / ParMETIS, absent or untested
  params.set("smoother: type", "RELAXATION");
  Teuchos::ParameterList smoother;
  smoother.set("relaxation: type", "Symmetric Gauss-Seidel");
  smoother.set("relaxation: sweeps", options.sweeps);
  smoother.set("relaxation: damping factor", options.damping);
  params.set("smoother: params", smoother);
  // MueLu's default coarse solver is KLU2: wrong on more than one rank (doc/architecture.md
  // "Trilinos and Debian").
  params.set("coarse: type", "RELAXATION");
  Teuchos::ParameterList coarse;
  coarse.set("relaxation: type", "Symmetric Gauss-Seidel");
  coarse.set("relaxation: sweeps", options.coarseSweeps);
  params.set("coarse: params", coarse);
  if (!nullSpace.is_null())
    params.sublist("user data").set("Nullspace", Teuchos::rcp_const_cast<MultiVector>(nullSpace));
  // MueLu takes a non-const operator but does not modify it.
  auto op = Teuchos::rcp_const_cast<Operator>(Teuchos::rcp_implicit_cast<const Operator>(A));
  return MueLu::CreateTpetraPreconditioner(op, params);
}

}  // namespace contactlab
