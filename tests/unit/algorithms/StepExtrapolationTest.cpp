// Newton/Extrapolation (StepExtrapolation, StaticSolver): a step starts from the last converged
// state moved by the last step's increment, scaled by this step's load increment (the plain
// start's residual r = R(u_n, t_{n+1})) projected on the last one's, a = r.r_n / r_n.r_n,
// clamped to [0, 2]. A load held or turned back starts from u_n. On a hardening spring
// x + x^3 = f(t) driven by its load, the extrapolated steps start nearer their roots (the
// same roots) and the step after the load's peak starts from u_n.
#include "ScalarSystem.hpp"

#include "algorithms/PlainNewton.hpp"
#include "algorithms/StaticSolver.hpp"
#include "algorithms/StepExtrapolation.hpp"
#include "linear/Klu2Solver.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace contactlab {
namespace {

Teuchos::RCP<Vector> vector2(double a, double b) {
  auto map = Teuchos::rcp(new Map(2, 0, Tpetra::getDefaultComm()));
  auto v = Teuchos::rcp(new Vector(map));
  if (map->isNodeGlobalElement(0)) v->replaceGlobalValue(0, a);
  if (map->isNodeGlobalElement(1)) v->replaceGlobalValue(1, b);
  return v;
}

// The last step went from (0, 0) to (1, 2) with load residual (-1, 0); the next starts with r.
double factorAfter(const Vector& r) {
  StepExtrapolation e;
  e.beginStep(*vector2(-1, 0));
  e.record(*vector2(0, 0), *vector2(1, 2));
  e.beginStep(r);
  return e.factor();
}

TEST(StepExtrapolation, ScalesTheLastIncrementByTheProjectedLoadIncrement) {
  EXPECT_DOUBLE_EQ(factorAfter(*vector2(-1, 0)), 1.0);    // the same load increment
  EXPECT_DOUBLE_EQ(factorAfter(*vector2(-0.5, 7)), 0.5);  // half of it along the last one
  EXPECT_DOUBLE_EQ(factorAfter(*vector2(-5, 0)), 2.0);    // at most twice the last step
  EXPECT_DOUBLE_EQ(factorAfter(*vector2(1, 0)), 0.0);     // the load turned back
  EXPECT_DOUBLE_EQ(factorAfter(*vector2(0, 0)), 0.0);     // the load held
  EXPECT_DOUBLE_EQ(factorAfter(*vector2(0, 3)), 0.0);     // another load
  StepExtrapolation e;
  e.beginStep(*vector2(-1, 0));
  e.record(*vector2(0, 0), *vector2(1, 2));
  auto x = vector2(0, 0);
  e.extrapolate(*vector2(1, 2), 0.5, *x);
  EXPECT_DOUBLE_EQ(x->getData(0)[0] + 0.0, x->getMap()->isNodeGlobalElement(0) ? 1.5 : 0.0);
}

TEST(StepExtrapolation, AStepRecordedWithoutItsLoadIsNotKnown) {
  StepExtrapolation e;
  e.beginStep(*vector2(-1, 0));
  e.record(*vector2(0, 0), *vector2(1, 2));
  e.skipStep();  // the next step's plain start could not be evaluated
  e.record(*vector2(1, 2), *vector2(2, 4));
  EXPECT_TRUE(e.increment().is_null());
  e.beginStep(*vector2(-1, 0));
  EXPECT_EQ(e.factor(), 0.0);
}

// x + x^3 = f(t), f rising to 4 at t = 4, then falling to 2 at t = 6: six steps.
struct SpringRun {
  RunReport report;
  std::vector<double> roots;
  std::vector<double> starts;  // the first x each step evaluates with its tangent
};

SpringRun runSpring(const std::string& extrapolation) {
  const auto load = [](double t) { return t <= 4 ? t : 8 - t; };
  SpringRun out;
  double lastTime = -1;
  test::ScalarSystem system([&](double x, double t) { return x + x * x * x - load(t); },
                            [&](double x, double t) {
                              if (t != lastTime) out.starts.push_back(x);
                              lastTime = t;
                              return 1 + 3 * x * x;
                            },
                            1.0);
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  PlainNewton newton(system, solver, nullptr);
  StaticSolverOptions options;
  options.steps = 6;
  options.endTime = 6;
  options.relativeTolerance = 1e-12;
  options.extrapolation = extrapolation;
  StaticSolver stepper(system, nullptr, newton, options, &solver);
  auto u = system.createVector();
  out.report = stepper.run(
      *u, [&](const StepReport&, const Vector& x) { out.roots.push_back(x.getData(0)[0]); });
  return out;
}

TEST(StepExtrapolation, StartsLoadDrivenStepsNearerTheirRootsAndNotPastAPeak) {
  const SpringRun plain = runSpring("none"), linear = runSpring("linear");
  ASSERT_TRUE(plain.report.converged) << plain.report.message;
  ASSERT_TRUE(linear.report.converged) << linear.report.message;
  ASSERT_EQ(linear.roots.size(), 6u);
  for (std::size_t k = 0; k < 6; ++k)
    EXPECT_NEAR(linear.roots[k], plain.roots[k], 1e-12);
  // Steps 2-4 extrapolate from the last two roots (the load rises by 1 each step); step 5,
  // after the peak, starts from the root at t = 4; step 6 extrapolates the fall.
  ASSERT_EQ(linear.starts.size(), 6u);
  EXPECT_NEAR(linear.starts[2], 2 * linear.roots[1] - linear.roots[0], 1e-12);
  EXPECT_NEAR(linear.starts[4], linear.roots[3], 1e-12);
  EXPECT_NEAR(linear.starts[5], 2 * linear.roots[4] - linear.roots[3], 1e-12);
  EXPECT_NEAR(plain.starts[2], plain.roots[1], 1e-12);
  for (std::size_t k : {2u, 3u, 5u})
    EXPECT_LT(std::abs(linear.starts[k] - linear.roots[k]),
              0.6 * std::abs(plain.starts[k] - plain.roots[k]))
        << "step " << k + 1;
}

// x^3 + x = t^3 + t over t = 1, 2, 3 (roots x = t): the third step's load increment (20) is 2.5
// times the second's (8), so its start is capped at a = 2: x = 2 + 2 (2 - 1) = 4, where this
// system cannot be evaluated (as an element turned inside out; 3.7 < x < 4.5). The step starts
// from u_n = 2 instead, and Newton from there stays below 3.7 (3.54, 3.08, ...).
class CubeWithAHole : public test::ScalarSystem {
 public:
  CubeWithAHole()
      : ScalarSystem([](double x, double t) { return x * x * x + x - t * t * t - t; },
                     [](double x, double) { return 3 * x * x + 1; }, 1.0) {}
  void assemble(const Vector& x, double t, Vector* residual, bool withTangent) override {
    const double value = x.getData(0)[0];
    evaluated.push_back(value);
    failed_ = value > 3.7 && value < 4.5;
    ScalarSystem::assemble(x, t, residual, withTangent);
  }
  AssemblyFailure assemblyFailure() const override {
    AssemblyFailure f;
    if (failed_) f.code = "inverted-element";
    return f;
  }
  std::vector<double> evaluated;

 private:
  bool failed_ = false;
};

TEST(StepExtrapolation, AGuessTheSystemCannotEvaluateFallsBackToThePlainStart) {
  CubeWithAHole system;
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  PlainNewton newton(system, solver, nullptr);
  StaticSolverOptions options;
  options.steps = 3;
  options.endTime = 3;
  options.extrapolation = "linear";
  StaticSolver stepper(system, nullptr, newton, options, &solver);
  auto u = system.createVector();
  std::vector<double> roots;
  const RunReport report = stepper.run(
      *u, [&](const StepReport&, const Vector& x) { roots.push_back(x.getData(0)[0]); });
  ASSERT_TRUE(report.converged) << report.message;
  EXPECT_EQ(report.cuts, 0);
  ASSERT_EQ(roots.size(), 3u);
  EXPECT_NEAR(roots[2], 3.0, 1e-10);
  // The guess (4 up to the roots' tolerance) was tried.
  EXPECT_TRUE(std::any_of(system.evaluated.begin(), system.evaluated.end(),
                          [](double x) { return std::abs(x - 4.0) < 1e-6; }));
}

}  // namespace
}  // namespace contactlab
