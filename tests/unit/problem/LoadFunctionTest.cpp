// The time functions of loads and prescribed values (Loads.hpp): known values of the ramp and
// of a table that rises and falls.
#include "core/problem/Loads.hpp"

#include <gtest/gtest.h>

namespace contactlab {
namespace {

TEST(LoadFunction, RampStartsStopsAndHolds) {
  LoadFunction f;
  f.startTime = 0.5;
  f.endTime = 1.5;
  EXPECT_EQ(f(0.0), 0.0);
  EXPECT_EQ(f(0.5), 0.0);
  EXPECT_DOUBLE_EQ(f(1.0), 0.5);
  EXPECT_EQ(f(1.5), 1.0);
  EXPECT_EQ(f(9.0), 1.0);
}

TEST(LoadFunction, TableInterpolatesAndHoldsItsEnds) {
  LoadFunction f;
  f.kind = LoadFunction::Kind::Table;
  f.times = {1.0, 2.0, 4.0};
  f.factors = {0.0, 1.0, -0.5};
  EXPECT_EQ(f(0.0), 0.0);  // before the first time: its factor
  EXPECT_EQ(f(1.0), 0.0);
  EXPECT_DOUBLE_EQ(f(1.25), 0.25);
  EXPECT_EQ(f(2.0), 1.0);  // the peak is a table time: reached exactly
  EXPECT_DOUBLE_EQ(f(3.0), 0.25);
  EXPECT_EQ(f(4.0), -0.5);
  EXPECT_EQ(f(7.0), -0.5);  // after the last: its factor
}

}  // namespace
}  // namespace contactlab
