#include "algorithms/SolidAlonePredictor.hpp"

#include "linear/BelosSolver.hpp"

namespace contactlab {

SolidAlonePredictor::SolidAlonePredictor(bool always) : always_(always) {}

SolidAlonePredictor::~SolidAlonePredictor() = default;

bool SolidAlonePredictor::step(ContactControls& controls, Vector& x, double t) {
  const auto solve = [this](const Teuchos::RCP<const Matrix>& tangent, const Vector& rhs,
                            Vector& du, int dofsPerNode) {
    if (!solver_) {
      BelosSolver::Options options;
      options.method = BelosSolver::Method::cg;
      options.tolerance = kTolerance;
      options.maxIterations = kMaxIterations;
      options.preconditioner.kind = PreconditionerOptions::Kind::muelu;
      options.preconditioner.blockSize = dofsPerNode;
      solver_ = std::make_unique<BelosSolver>(options, tangent->getComm());
    }
    try {
      solver_->setMatrix(tangent, true);
      solver_->solve(rhs, du);
    } catch (const LinearSolverError&) {
      return false;  // not converged, or the hierarchy failed: Newton's own first iteration
    }
    return true;
  };
  return controls.stepSolidAlone(x, t, always_ ? 0 : kMinimumDofs, solve);
}

}  // namespace contactlab
