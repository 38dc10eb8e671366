// Newton stops at the round-off floor of its residual (residualRoundoff) instead of cycling
// there to a failure: R(x) = x - a with a = 1e12 and a round-off-like term of half (or twice)
// eps |dR/dx| |x| whose sign alternates at each evaluation, so no iterate reaches the 1e-12
// asked. The half passes as converged at the floor (counted) where the request allows it (a
// solve a fixed-point update follows); twice the floor does not, nor the half where it does not.
#include "ScalarSystem.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace contactlab {
namespace {

NewtonOutcome solveWithNoise(double noiseOverFloor, bool roundoffStop = true) {
  constexpr double a = 1e12;
  int evaluations = 0;
  test::ScalarSystem system(
      [&](double x, double) {
        const double floor = std::numeric_limits<double>::epsilon() * std::abs(x);
        return (x - a) + (evaluations++ % 2 ? -1.0 : 1.0) * noiseOverFloor * floor;
      },
      [](double, double) { return 1.0; }, 1.0);
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  PlainNewton newton(system, solver, nullptr);
  auto x = system.createVector();
  NewtonRequest request = test::newtonRequest(1e-12, 10);
  request.roundoffStop = roundoffStop;
  return newton.solve(*x, request, {});
}

TEST(RoundoffStop, AResidualAtItsRoundoffFloorIsConverged) {
  const NewtonOutcome out = solveWithNoise(0.5);
  ASSERT_TRUE(out.failure.empty()) << out.failure << ": " << out.message;
  EXPECT_EQ(out.roundoffStops, 1);
  EXPECT_LE(out.iterations, 2);
}

TEST(RoundoffStop, NotWhereTheRequestDoesNotAllowIt) {
  const NewtonOutcome out = solveWithNoise(0.5, false);
  EXPECT_EQ(out.failure, "max-iterations");
  EXPECT_EQ(out.roundoffStops, 0);
}

TEST(RoundoffStop, AResidualAboveTheFloorIsNot) {
  const NewtonOutcome out = solveWithNoise(2.0);
  EXPECT_EQ(out.failure, "max-iterations");
  EXPECT_EQ(out.roundoffStops, 0);
}

}  // namespace
}  // namespace contactlab
