// NewtonRequest::forcing: PlainNewton stops at forcing times its first ||R|| (an inexact solve
// between two fixed-point updates, doc/algorithms.md "Inexact solves between fixed-point
// updates"), never below the target it would stop at anyway. The residual histories are
// scripted: the system returns the next value of its list at each evaluation.
#include "ScalarSystem.hpp"

#include <gtest/gtest.h>

namespace contactlab {
namespace {

NewtonOutcome solveWithForcing(double forcing) {
  NewtonRequest request = test::newtonRequest(1e-10, 20);
  request.forcing = forcing;
  return test::solveScripted({1, 1e-1, 1e-3, 1e-6, 1e-12}, request);
}

TEST(NewtonForcing, StopsAtTheForcingTimesTheFirstResidual) {
  EXPECT_EQ(solveWithForcing(0).iterations, 4);     // to 1e-12 <= 1e-10
  EXPECT_EQ(solveWithForcing(1e-2).iterations, 2);  // to 1e-3 <= 1e-2 x 1
  EXPECT_EQ(solveWithForcing(1e-2).residual, 1e-3);
  EXPECT_EQ(solveWithForcing(1e-12).iterations, 4);  // the target is the floor: 1e-10
}

}  // namespace
}  // namespace contactlab
