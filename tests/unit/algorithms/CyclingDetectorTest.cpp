// Cycling detection on known state sequences: each kind of the seed's decomposition and of
// Code_Aster's friction cycles, and the sequences that must not count (convergence, round-off
// flips of a closed point's gap, a single change of status).
#include "algorithms/CyclingDetector.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace contactlab {
namespace {

ContactPointState state(int zone, double gap, int status = -1) {
  ContactPointState s;
  s.zone = zone;
  s.gap = gap;
  s.status = status >= 0 ? status : (zone >= 3 ? 1 : 0);
  s.length = 1.0;
  return s;
}

// Feeds one point's sequence; returns the kinds reported, in order.
std::vector<CyclingKind> feed(const std::vector<ContactPointState>& sequence,
                              double grazingTolerance = 1e-6) {
  CyclingDetector detector(grazingTolerance);
  std::vector<CyclingKind> kinds;
  for (const auto& s : sequence)
    for (const auto& e : detector.observe({s}))
      kinds.push_back(e.kind);
  return kinds;
}

TEST(CyclingDetector, SubCycling1IsZones1313) {
  const auto k = feed({state(1, 0.1), state(3, -0.1), state(1, 0.1), state(3, -0.1)});
  ASSERT_EQ(k.size(), 1u);
  EXPECT_EQ(k[0], CyclingKind::SubCycling1);
}

TEST(CyclingDetector, SubCycling2IsZones2424) {
  const auto k = feed({state(2, -0.1), state(4, 0.1), state(2, -0.1), state(4, 0.1)});
  ASSERT_EQ(k.size(), 1u);
  EXPECT_EQ(k[0], CyclingKind::SubCycling2);
}

TEST(CyclingDetector, GrazingIsZones2323WithSmallGaps) {
  const auto small = feed({state(2, -1e-9), state(3, -1e-9), state(2, -1e-9), state(3, -1e-9)});
  ASSERT_EQ(small.size(), 1u);
  EXPECT_EQ(small[0], CyclingKind::Grazing);
  // The same zones with gaps of the point's size are an ordinary status flip-flop.
  const auto large = feed({state(2, -0.5), state(3, -0.5), state(2, -0.5), state(3, -0.5)});
  ASSERT_EQ(large.size(), 1u);
  EXPECT_EQ(large[0], CyclingKind::ContactFlipFlop);
}

TEST(CyclingDetector, StickSlipFlipFlop) {
  const auto k = feed({state(3, 0, 1), state(3, 0, 2), state(3, 0, 1), state(3, 0, 2)});
  ASSERT_EQ(k.size(), 1u);
  EXPECT_EQ(k[0], CyclingKind::StickSlip);
}

TEST(CyclingDetector, SlipReversalIsTwoReversalsInARow) {
  auto slip = [](double direction) {
    ContactPointState s = state(3, 0, 2);
    s.traction = {direction, 0, 0};
    return s;
  };
  EXPECT_TRUE(feed({slip(1), slip(1), slip(-1)}).empty());  // one reversal: a real change
  const auto k = feed({slip(1), slip(-1), slip(1)});
  ASSERT_EQ(k.size(), 1u);
  EXPECT_EQ(k[0], CyclingKind::SlipReversal);
}

TEST(CyclingDetector, RepeatsAndRoundOffAreNotCycles) {
  // Converging: free, then closed for good (repeats merge).
  EXPECT_TRUE(feed({state(1, 0.1), state(3, -0.1), state(3, -0.01), state(3, 0)}).empty());
  // A closed point whose gap flips sign at round-off level (zones 3 <-> 4, status unchanged).
  EXPECT_TRUE(
      feed({state(3, -1e-17), state(4, 1e-17), state(3, -1e-17), state(4, 1e-17), state(3, -1e-17)})
          .empty());
  // Three alternations are not yet a cycle.
  EXPECT_TRUE(feed({state(1, 0.1), state(3, -0.1), state(1, 0.1)}).empty());
}

TEST(CyclingDetector, ResetForgetsTheHistory) {
  CyclingDetector detector;
  detector.observe({state(1, 0.1)});
  detector.observe({state(3, -0.1)});
  detector.observe({state(1, 0.1)});
  detector.reset();
  EXPECT_TRUE(detector.observe({state(3, -0.1)}).empty());
}

// The friction cycle the forced treatment made of its own decisions (the axisymmetric tube with
// friction under the fixed point): stick-slip forces slip, the forced slip reverses twice and
// is forced to stick, and that stick, read as a fourth alternation of the point's history,
// forced slip again, every fourth Newton iterate until max-iterations. The treatment forgets a
// point's history when it forces it (StaticSolver::treatCycling).
TEST(CyclingDetector, AForcedStatusStartsTheHistoryOver) {
  auto slip = [](double direction) {
    ContactPointState s = state(3, 0, 2);
    s.traction = {direction, 0, 0};
    return s;
  };
  const auto stickSlipThenReversal = [&](bool forget) {
    CyclingDetector detector;
    std::vector<CyclingKind> kinds;
    const auto observe = [&](const ContactPointState& s) {
      for (const auto& e : detector.observe({s})) {
        kinds.push_back(e.kind);
        if (forget) detector.forget(e.point);
      }
    };
    for (const auto& s : {state(3, 0, 1), slip(1), state(3, 0, 1), slip(1)})
      observe(s);  // stick-slip: forced to slip
    for (const auto& s : {slip(-1), slip(1), slip(-1)})
      observe(s);  // the forced slip reverses twice: forced to stick
    observe(state(3, 0, 1));
    observe(state(3, 0, 1));
    return kinds;
  };
  const auto treated = stickSlipThenReversal(true);
  ASSERT_EQ(treated.size(), 2u);
  EXPECT_EQ(treated[0], CyclingKind::StickSlip);
  EXPECT_EQ(treated[1], CyclingKind::SlipReversal);
  // Without forgetting, the forced stick is one more stick-slip alternation.
  const auto remembered = stickSlipThenReversal(false);
  ASSERT_EQ(remembered.size(), 3u);
  EXPECT_EQ(remembered[2], CyclingKind::StickSlip);
}

TEST(CyclingDetector, KindNamesAreDistinct) {
  for (int a = 0; a < kCyclingKinds; ++a)
    for (int b = a + 1; b < kCyclingKinds; ++b)
      EXPECT_STRNE(cyclingKindName(static_cast<CyclingKind>(a)),
                   cyclingKindName(static_cast<CyclingKind>(b)));
}

}  // namespace
}  // namespace contactlab
