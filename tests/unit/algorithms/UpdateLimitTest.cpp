// Newton/Max Update on R(x, t) = atan(x - a t), one unknown: from x = 0, full Newton steps
// overshoot and diverge once the root is farther than about 1.39 (the textbook case of a
// tangent that flattens away from the root, as a perfectly plastic body's does past its limit
// load). The step is then solved again with the updates scaled down to the limit: they walk to
// the root and then converge quadratically. A step that converges with full steps, or whose
// failed updates were all shorter than the limit, is not solved again.
#include "ScalarSystem.hpp"

#include "algorithms/PlainNewton.hpp"
#include "algorithms/StaticSolver.hpp"
#include "linear/Klu2Solver.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

// R(x, t) = atan(x - root t).
test::ScalarSystem arctan(double root, double size) {
  return test::ScalarSystem([root](double x, double t) { return std::atan(x - root * t); },
                            [root](double x, double t) {
                              const double d = x - root * t;
                              return 1 / (1 + d * d);
                            },
                            size);
}

struct Outcome {
  RunReport report;
  double x = 0;
};

// One load step to t = 1, no cut, no line-search retry.
Outcome run(double root, double maxUpdate, double size = 10.0, int maxIterations = 20) {
  test::ScalarSystem system = arctan(root, size);
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
