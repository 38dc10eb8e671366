// An update that lands where the system cannot be evaluated (a NaN residual: an element
// inverted, a mortar facet without a dual basis) is halved until it can, instead of failing
// the Newton solve (PETSc's SNES does so after a function domain error). The scalar law
// R(x) = x^3 - 8, evaluable only for x <= 3: from x = 1 the full step lands at 10/3.
#include "ScalarSystem.hpp"

#include "algorithms/PlainNewton.hpp"
#include "linear/Klu2Solver.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace contactlab {
namespace {

NewtonRequest request() {
  NewtonRequest r;
  r.time = 1;
  r.target = 1e-12;
  r.maxIterations = 20;
  return r;
}

double cubeMinusEight(double x, double bound) {
  return x <= bound ? x * x * x - 8 : std::numeric_limits<double>::quiet_NaN();
}

TEST(UnevaluableIterate, AnUpdateIntoTheUnevaluableRegionIsHalved) {
  test::ScalarSystem system([](double x, double) { return cubeMinusEight(x, 3.0); },
                            [](double x, double) { return 3 * x * x; }, 1.0);
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  PlainNewton newton(system, solver, nullptr);
  auto x = system.createVector();
  x->putScalar(1.0);
  const NewtonOutcome out = newton.solve(*x, request(), {});
  ASSERT_TRUE(out.failure.empty()) << out.failure << ": " << out.message;
  EXPECT_NEAR(x->getData(0)[0], 2.0, 1e-12);
  EXPECT_EQ(out.unevaluableHalvings, 1);  // 10/3, then 13/6
}

// Where no fraction of the update down to 1/1024 can be evaluated, the solve fails as before,
// at the last halving's iterate.
TEST(UnevaluableIterate, AnUpdateThatNoHalvingSavesFails) {
  test::ScalarSystem system([](double x, double) { return cubeMinusEight(x, 1.0); },
                            [](double x, double) { return 3 * x * x; }, 1.0);
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  PlainNewton newton(system, solver, nullptr);
  auto x = system.createVector();
  x->putScalar(1.0);
  const NewtonOutcome out = newton.solve(*x, request(), {});
  EXPECT_EQ(out.failure, "nan-detected");
  EXPECT_EQ(out.unevaluableHalvings, kUnevaluableHalvings);
  EXPECT_NEAR(x->getData(0)[0], 1.0 + (7.0 / 3.0) / 1024, 1e-12);
}

}  // namespace
}  // namespace contactlab
