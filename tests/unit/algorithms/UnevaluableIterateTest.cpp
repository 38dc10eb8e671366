// An update that lands where the system cannot be evaluated (a NaN residual: an element
// inverted, a mortar facet without a dual basis) is halved until it can, instead of failing
// the Newton solve (PETSc's SNES does so after a function domain error); NOX's backtracking
// shortens such a step by itself. The scalar law
// R(x) = x^3 - 8, evaluable only for x <= 3: from x = 1 the full step lands at 10/3.
#include "ScalarSystem.hpp"

#include "algorithms/NoxNewton.hpp"
#include "algorithms/PlainNewton.hpp"
#include "linear/Klu2Solver.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace contactlab {
namespace {

// R(x) = x^3 - 8, evaluable for x <= bound only.
test::ScalarSystem cubeMinusEight(double bound) {
  return test::ScalarSystem(
      [bound](double y, double) {
        return y <= bound ? y * y * y - 8 : std::numeric_limits<double>::quiet_NaN();
      },
      [](double y, double) { return 3 * y * y; }, 1.0);
}

// Plain Newton on cubeMinusEight(bound) from x = 1; x: the last iterate.
NewtonOutcome solveFromOne(double bound, double& x) {
  test::ScalarSystem system = cubeMinusEight(bound);
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  PlainNewton newton(system, solver, nullptr);
  auto v = system.createVector();
  v->putScalar(1.0);
  const NewtonOutcome out = newton.solve(*v, test::newtonRequest(1e-12, 20), {});
  x = v->getData(0)[0];
  return out;
}

TEST(UnevaluableIterate, AnUpdateIntoTheUnevaluableRegionIsHalved) {
  double x = 0;
  const NewtonOutcome out = solveFromOne(3.0, x);
  ASSERT_TRUE(out.failure.empty()) << out.failure << ": " << out.message;
  EXPECT_NEAR(x, 2.0, 1e-12);
  EXPECT_EQ(out.unevaluableHalvings, 1);  // 10/3, then 13/6
}

// Where no fraction of the update down to 1/1024 can be evaluated, the solve fails as before,
// at the last halving's iterate.
TEST(UnevaluableIterate, AnUpdateThatNoHalvingSavesFails) {
  double x = 0;
  const NewtonOutcome out = solveFromOne(1.0, x);
  EXPECT_EQ(out.failure, "nan-detected");
  EXPECT_EQ(out.unevaluableHalvings, kUnevaluableHalvings);
  EXPECT_NEAR(x, 1.0 + (7.0 / 3.0) / 1024, 1e-12);
}

// NOX's backtracking line search rejects a trial point whose residual is not finite and
// halves the step, so the line-search retry may follow a step that failed on an unevaluable
// iterate (StaticSolver retries such failures).
TEST(UnevaluableIterate, NoxBacktrackingShortensAStepIntoTheUnevaluableRegion) {
  test::ScalarSystem system = cubeMinusEight(3.0);
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  NoxNewton newton(system, solver, nullptr, "Backtrack");
  auto v = system.createVector();
  v->putScalar(1.0);
  const NewtonOutcome out = newton.solve(*v, test::newtonRequest(1e-12, 20), {});
  ASSERT_TRUE(out.failure.empty()) << out.failure << ": " << out.message;
  EXPECT_NEAR(v->getData(0)[0], 2.0, 1e-12);
}

}  // namespace
}  // namespace contactlab
