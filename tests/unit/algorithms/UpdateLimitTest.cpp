// Newton/Max Update on R(x, t) = atan(x - a t), one unknown: from x = 0, full Newton steps
// overshoot and diverge once the root is farther than about 1.39 (the textbook case of a
// tangent that flattens away from the root, as a perfectly plastic body's does past its limit
// load). The step is then solved again with the updates scaled down to the limit: they walk to
// the root and then converge quadratically. A step that converges with full steps, or whose
// failed updates were all shorter than the limit, is not solved again.
#include "algorithms/PlainNewton.hpp"
#include "algorithms/StaticSolver.hpp"
#include "linear/Klu2Solver.hpp"

#include <Tpetra_Core.hpp>

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

class ArctanSystem : public NonlinearSystem {
 public:
  ArctanSystem(double root, double size) : root_(root), size_(size) {
    map_ = Teuchos::rcp(new Map(1, 0, Tpetra::getDefaultComm()));
    tangent_ = Teuchos::rcp(new Matrix(map_, 1));
    const GO col = 0;
    const double zero = 0;
    tangent_->insertGlobalValues(0, 1, &zero, &col);
    tangent_->fillComplete();
  }
  Teuchos::RCP<Vector> createVector() const override { return Teuchos::rcp(new Vector(map_)); }
  void applyDirichlet(double, Vector&) const override {}
  void assemble(const Vector& xv, double t, Vector* residual, bool withTangent) override {
    const double d = xv.getData(0)[0] - root_ * t;
    if (residual) residual->getDataNonConst(0)[0] = std::atan(d);
    if (withTangent) {
      tangent_->resumeFill();
      const GO col = 0;
      const double k = 1 / (1 + d * d);
      tangent_->replaceGlobalValues(0, 1, &k, &col);
      tangent_->fillComplete();
    }
  }
  const Teuchos::RCP<Matrix>& tangent() const override { return tangent_; }
  void commitState(const Vector&, double) override {}
  double modelSize() const override { return size_; }

 private:
  double root_, size_;
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<Matrix> tangent_;
};

struct Outcome {
  RunReport report;
  double x = 0;
};

// One load step to t = 1, no cut, no line-search retry.
Outcome run(double root, double maxUpdate, double size = 10.0, int maxIterations = 20) {
  ArctanSystem system(root, size);
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  PlainNewton newton(system, solver, nullptr);
  StaticSolverOptions options;
  options.maxUpdate = maxUpdate;
  options.lineSearchRetry = "never";
  options.relativeTolerance = 1e-12;
  options.maxIterations = maxIterations;
  options.maxCuts = 0;
  StaticSolver stepper(system, nullptr, newton, options, &solver);
  auto x = system.createVector();
  Outcome out;
  out.report = stepper.run(*x, {});
  out.x = x->getData(0)[0];
  return out;
}

TEST(UpdateLimit, FullStepsOvershootARootBeyondTheFlatTangent) {
  const Outcome full = run(3.0, 0.0);
  EXPECT_FALSE(full.report.converged);
}

TEST(UpdateLimit, AFailedStepIsSolvedAgainWithScaledUpdatesThatWalkToTheRoot) {
  // The limit is 0.05 of the model size 10: 0.5 per update.
  const Outcome full = run(3.0, 0.0), limited = run(3.0, 0.05);
  ASSERT_TRUE(limited.report.converged) << limited.report.message;
  EXPECT_NEAR(limited.x, 3.0, 1e-10);
  // The full steps' failed attempt, then six updates of 0.5 to the root's neighbourhood and a
  // few quadratic ones.
  EXPECT_GE(limited.report.limitedUpdates, 5);
  EXPECT_GE(limited.report.iterations, full.report.iterations + 6);
  EXPECT_LE(limited.report.iterations, full.report.iterations + 12);
}

TEST(UpdateLimit, AStepThatConvergesWithFullStepsIsNotLimited) {
  // The first update from 0 is atan(0.3) (1 + 0.09) = 0.318: converges with full steps.
  const Outcome full = run(0.3, 0.0), limited = run(0.3, 0.001);
  ASSERT_TRUE(full.report.converged && limited.report.converged);
  EXPECT_EQ(limited.report.limitedUpdates, 0);
  EXPECT_EQ(limited.report.iterations, full.report.iterations);
  EXPECT_EQ(limited.x, full.x);
}

TEST(UpdateLimit, AFailedStepWhoseUpdatesWereShorterThanTheLimitIsNotSolvedAgain) {
  // One iteration allowed: the update 12.5 fails the step; the limit is 0.05 x 1000 = 50, so a
  // second try would take the same step and fail the same way.
  const Outcome limited = run(3.0, 0.05, 1000.0, 1);
  EXPECT_FALSE(limited.report.converged);
  EXPECT_EQ(limited.report.failure, "max-iterations");
  EXPECT_EQ(limited.report.iterations, 1);
  EXPECT_EQ(limited.report.limitedUpdates, 0);
}

}  // namespace
}  // namespace contactlab
