// A singular Newton tangent is named: `singular-tangent`, with the iteration, the step and the
// remedies, whether the direct solver meets an exact zero pivot (MUMPS INFOG(1) = -10) or
// only a round-off one (the increment then proves the matrix singular). The system is linear,
// R(x) = A x - (1, 0) with A = [[1, 1], [1, 1 + d]]: d = 0 is singular, d = 1e-15 is singular to
// working precision (its second pivot is the round-off of a motion that nothing holds; no
// scaling of the rows makes it regular, unlike diag(1, d)), d = 1e-6 is regular.
#include "algorithms/PlainNewton.hpp"
#include "algorithms/StaticSolver.hpp"
#include "linear/MumpsSolver.hpp"

#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>

namespace contactlab {
namespace {

class CoupledSystem : public NonlinearSystem {
 public:
  explicit CoupledSystem(double d)
      : d_(d), map_(Teuchos::rcp(new Map(2, 0, Tpetra::getDefaultComm()))) {
    tangent_ = Teuchos::rcp(new Matrix(map_, 2));
    for (LO i = 0; i < static_cast<LO>(map_->getNodeNumElements()); ++i) {
      const GO g = map_->getGlobalElement(i);
      tangent_->insertGlobalValues(g, Teuchos::tuple<GO>(0, 1),
                                   Teuchos::tuple(1.0, g == 0 ? 1.0 : 1.0 + d_));
    }
    tangent_->fillComplete();
  }

  Teuchos::RCP<Vector> createVector() const override { return Teuchos::rcp(new Vector(map_)); }
  void applyDirichlet(double, Vector&) const override {}
  void assemble(const Vector& x, double, Vector* residual, bool) override {
    if (!residual) return;
    tangent_->apply(x, *residual);
    for (std::size_t i = 0; i < residual->getLocalLength(); ++i)
      if (map_->getGlobalElement(static_cast<LO>(i)) == 0) residual->getDataNonConst(0)[i] -= 1.0;
  }
  const Teuchos::RCP<Matrix>& tangent() const override { return tangent_; }
  void commitState(const Vector&, double) override {}

 private:
  double d_;
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<Matrix> tangent_;
};

RunReport runWith(double d) {
  CoupledSystem system(d);
  MumpsSolver solver(MumpsSolver::Options{}, Tpetra::getDefaultComm());
  PlainNewton newton(system, solver, nullptr);
  StaticSolver run(system, nullptr, newton, StaticSolverOptions{});
  auto u = system.createVector();
  return run.run(*u, {});
}

void expectNamed(const RunReport& report, const std::string& detail) {
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.failure, "singular-tangent") << report.message;
  for (const char* part : {"the tangent is singular at iteration 0", "at step 1",
                           "a body is not held in some direction",
                           "Algorithm/Regularization: slow-dynamics", "Initial Contact: all"})
    EXPECT_NE(report.message.find(part), std::string::npos) << part << " in " << report.message;
  EXPECT_NE(report.message.find(detail), std::string::npos) << report.message;
}

TEST(SingularTangent, AZeroPivotIsNamed) {
  expectNamed(runWith(0.0), "INFOG(1) = -10");
}

TEST(SingularTangent, ARoundOffPivotIsNamed) {
  expectNamed(runWith(1e-15), "proves cond(D A D) >=");
}

TEST(SingularTangent, AnIllConditionedButRegularTangentConverges) {
  const RunReport report = runWith(1e-6);
  EXPECT_TRUE(report.converged) << report.failure << ": " << report.message;
}

}  // namespace
}  // namespace contactlab
