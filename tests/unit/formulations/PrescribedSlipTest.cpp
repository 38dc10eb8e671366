// Known answers of the prescribed-slip detection (PrescribedSlip.hpp): which directions of the
// tangent plane the Dirichlet conditions fix, and the rows that drop their multipliers.
#include "formulations/PrescribedSlip.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

// One slave node on a rigid plane z = 0 (3 dofs), tangents t1, t2 in the plane: B rows
// (gap, slip 1, slip 2) = (n, t1, t2).
std::vector<double> pointOnAPlane(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {0, 0, 1, c, s, 0, -s, c, 0};
}

TEST(PrescribedSlip, FreeTangentialMotionPrescribesNothing) {
  EXPECT_EQ(prescribedSlip(pointOnAPlane(0.3), 2, 3, {1, 1, 1}).prescribed, 0);
  EXPECT_EQ(prescribedSlip(pointOnAPlane(0.3), 2, 3, {1, 1, 0}).prescribed, 0);  // z fixed
}

TEST(PrescribedSlip, BothTangentsFixedAtACorner) {
  EXPECT_EQ(prescribedSlip(pointOnAPlane(0.3), 2, 3, {0, 0, 1}).prescribed, 2);
}

TEST(PrescribedSlip, TheGapIsPrescribedOnlyWhenNoFreeDofMovesIt) {
  // Against a rigid plane the gap row is (0, 0, 1) on the slave's dofs.
  EXPECT_FALSE(prescribedGap(pointOnAPlane(0.3), 3, {1, 1, 1}));
  EXPECT_FALSE(prescribedGap(pointOnAPlane(0.3), 3, {0, 0, 1}));  // held tangentially only
  EXPECT_TRUE(prescribedGap(pointOnAPlane(0.3), 3, {1, 1, 0}));   // held normally
  EXPECT_TRUE(prescribedGap(pointOnAPlane(0.3), 3, {0, 0, 0}));   // clamped
  // 2D, a slave node against a master segment (nodes a, b) at its node a, N = (1, 0): with the
  // slave and a held, b's dofs carry no share of the gap; at N = (0.9, 0.1) they do.
  const std::vector<char> heldAtA = {0, 0, 0, 0, 1, 1};
  EXPECT_TRUE(prescribedGap({0, 1, 0, -1, 0, 0}, 6, heldAtA));
  EXPECT_FALSE(prescribedGap({0, 1, 0, -0.9, 0, -0.1}, 6, heldAtA));
  // An inclined symmetry plane's normal removed from the free motion of a node held otherwise.
  EXPECT_TRUE(prescribedGap({0, 1}, 2, {0, 1}, {{0, 1}}));
}

TEST(PrescribedSlip, ASymmetryPlaneFixesOneDirectionWhateverTheTangentBasis) {
  // x fixed (plane x = 0): the free direction is y, in (t1, t2) coordinates (sin a, cos a).
  const double a = 0.3;
  const PrescribedSlip s = prescribedSlip(pointOnAPlane(a), 2, 3, {0, 1, 1});
  ASSERT_EQ(s.prescribed, 1);
  const double fy1 = std::sin(a), fy2 = std::cos(a);
  EXPECT_NEAR(std::abs(s.basis[0][0] * fy1 + s.basis[1][0] * fy2), 1.0, 1e-14);  // free column
  EXPECT_NEAR(s.basis[0][1] * fy1 + s.basis[1][1] * fy2, 0.0, 1e-14);  // prescribed column
}

TEST(PrescribedSlip, AnInclinedSymmetryPlaneFixesItsNormalDirection) {
  // The plane through the z axis at 35 degrees (normal m = (-sin b, cos b, 0)) removes m from
  // the free motion: the slip along m is prescribed, the one along the plane's in-plane
  // tangent free. In (t1, t2) coordinates, m is (cos(b - a), sin(b - a)) rotated by 90 degrees.
  const double a = 0.3, b = 35.0 * M_PI / 180.0;
  const std::vector<double> m{-std::sin(b), std::cos(b), 0};
  const PrescribedSlip s = prescribedSlip(pointOnAPlane(a), 2, 3, {1, 1, 1}, {m});
  ASSERT_EQ(s.prescribed, 1);
  const double m1 = m[0] * std::cos(a) + m[1] * std::sin(a);                   // m . t1
  const double m2 = -m[0] * std::sin(a) + m[1] * std::cos(a);                  // m . t2
  EXPECT_NEAR(std::abs(s.basis[0][1] * m1 + s.basis[1][1] * m2), 1.0, 1e-14);  // prescribed: m
  EXPECT_NEAR(s.basis[0][0] * m1 + s.basis[1][0] * m2, 0.0, 1e-14);
  // A plane whose normal is the contact normal (z) removes no tangential motion.
  EXPECT_EQ(prescribedSlip(pointOnAPlane(a), 2, 3, {1, 1, 1}, {{0, 0, 1}}).prescribed, 0);
}

// A slave node on a symmetry plane against a faceted master: the master point lies a little
// inside a facet whose other nodes are off the plane, so B moves the slip along the plane's
// normal through them, by a shape value of 2 % (the tube expansion's hole). The free part of
// that direction is 4e-4 of the operator: kept by B alone, it is dropped by symmetry.
std::vector<double> slaveOnAPlaneAgainstAFacet(double shape) {
  // dofs: slave (x, y, z), master node on the plane, master node off it; the plane is y = 0
  // (normal e_y), the contact normal x, t1 = z, t2 = y. The slave's y is fixed.
  const double nOn = 1 - shape, nOff = shape;
  return {1, 0, 0, -nOn, 0,    0,    -nOff, 0,     0,      // gap: x
          0, 0, 1, 0,    0,    -nOn, 0,     0,     -nOff,  // slip 1: z
          0, 1, 0, 0,    -nOn, 0,    0,     -nOff, 0};     // slip 2: y
}

TEST(PrescribedSlip, ASymmetryPlaneThroughTheSlaveNodeDropsItsDirectionWhateverTheMaster) {
  const auto B = slaveOnAPlaneAgainstAFacet(0.02);
  const std::vector<char> free{1, 0, 1, 1, 0, 1, 1, 1, 1};  // the off-plane master moves in y
  EXPECT_EQ(prescribedSlip(B, 2, 9, free).prescribed, 0);   // B alone keeps y
  const PrescribedSlip s = prescribedSlip(B, 2, 9, free, {}, {{0.0, 1.0}});  // e_y: (t1, t2)
  ASSERT_EQ(s.prescribed, 1);
  EXPECT_NEAR(std::abs(s.basis[1][1]), 1.0, 1e-14);  // prescribed column: t2 = y
  EXPECT_NEAR(std::abs(s.basis[0][0]), 1.0, 1e-14);  // free column: t1 = z
  // z fixed everywhere too: nothing is left free.
  const std::vector<char> zFixed{1, 0, 0, 1, 0, 0, 1, 1, 0};
  EXPECT_EQ(prescribedSlip(B, 2, 9, zFixed, {}, {{0.0, 1.0}}).prescribed, 2);
  // Two planes through the node (an edge of the sector) prescribe both directions.
  EXPECT_EQ(prescribedSlip(B, 2, 9, free, {}, {{0.0, 1.0}, {1.0, 0.0}}).prescribed, 2);
  // A plane whose normal is the contact normal (n . t small) prescribes nothing.
  EXPECT_EQ(prescribedSlip(B, 2, 9, free, {}, {{0.1, 0.1}}).prescribed, 0);
}

TEST(PrescribedSlip, TwoDimensionsOnASymmetryAxis) {
  // 2D: (gap, slip) = (y, x) on one node; x fixed.
  EXPECT_EQ(prescribedSlip({0, 1, 1, 0}, 1, 2, {0, 1}).prescribed, 1);
  EXPECT_EQ(prescribedSlip({0, 1, 1, 0}, 1, 2, {1, 0}).prescribed, 0);
  // The symmetry axis x = 0 through the slave node: its normal is the tangent.
  EXPECT_EQ(prescribedSlip({0, 1, 1, 0}, 1, 2, {1, 0}, {}, {{1.0, 0.0}}).prescribed, 1);
}

// The axisymmetric tube expansion's first slave node with friction: tube and tubesheet both held
// axially at the joint's end, so the slave node and the master node facing it are fixed along
// the tangent (y). Once the tube has expanded, the node's mortar row also reaches two free
// master nodes of the next facet, with coefficients 1.5e-5 and 3.1e-5 (measured). That free
// part, 2.4e-5 of the operator, cannot carry the multiplier: kept, it took 8e7 at the next
// Newton iterate and the step failed at every cut (doc/verification.md, "Tube expansion").
TEST(PrescribedSlip, AMortarRowThatBarelyReachesFreeNodesIsPrescribed) {
  // dofs (r, y) of the slave node, the held master node, two free master nodes; 2D: (gap, slip).
  const std::vector<double> B{1,         0,         -1,         0,       -1e-6,     0,
                              -2e-6,     0,         2.269e-6,   -1.0,    -2.269e-6, 1.0,
                              3.471e-11, -1.530e-5, -6.943e-11, 3.059e-5};
  const std::vector<char> free{1, 0, 1, 0, 1, 1, 1, 1};
  EXPECT_EQ(prescribedSlip(B, 1, 8, free).prescribed, 1);
  // A free part of 0.5 % of the operator still carries friction.
  std::vector<double> reaching = B;
  reaching[8 + 7] = 5e-3;
  EXPECT_EQ(prescribedSlip(reaching, 1, 8, free).prescribed, 0);
}

TEST(PrescribedSlip, ADirectionTheSupportsSlideSlipsOneTheyHoldIsDropped) {
  // A node on a fixed plane whose tangential dofs the supports fix (a pulled tube's end node).
  const PrescribedSlip held = prescribedSlip(pointOnAPlane(0.3), 2, 3, {0, 0, 1});
  ASSERT_EQ(held.prescribed, 2);
  EXPECT_TRUE(held.bySupports);
  // Moved by the supports along t1: it slips; held (or moved along the normal only, with the
  // round-off of a rotated basis along t1): it does not.
  EXPECT_TRUE(prescribedDirectionSlides(held, 2, {1e-3, 0}, 1e-3));
  EXPECT_FALSE(prescribedDirectionSlides(held, 2, {0, 0}, 0));
  EXPECT_FALSE(prescribedDirectionSlides(held, 2, {1e-20, 0}, 1e-3));
  // A symmetry plane's direction is never the supports' (its traction is zero by symmetry), nor
  // one prescribed because its free part is a sliver (the multiplier it would need).
  const PrescribedSlip symmetric = prescribedSlip(slaveOnAPlaneAgainstAFacet(0.02), 2, 9,
                                                  {1, 0, 1, 1, 0, 1, 1, 1, 1}, {}, {{0.0, 1.0}});
  ASSERT_EQ(symmetric.prescribed, 1);
  EXPECT_FALSE(prescribedDirectionSlides(symmetric, 2, {0, 1e-3}, 1e-3));
  // One friction direction (t1 = x) whose operator reaches a free master dof by 1e-4.
  const std::vector<double> B{0, 0, 1, 0,      // gap: z
                              1, 0, 0, 1e-4};  // slip 1: x, and the master dof
  const PrescribedSlip bySliver = prescribedSlip(B, 1, 4, {0, 0, 1, 1});
  ASSERT_EQ(bySliver.prescribed, 1);
  EXPECT_FALSE(bySliver.bySupports);
  EXPECT_FALSE(prescribedDirectionSlides(bySliver, 1, {1e-3, 0}, 1e-3));
}

TEST(PrescribedSlip, TheDroppedMultiplierIsZeroAndTheOtherRowIsKept) {
  // A law of size 6 (g, v1, v2, p, L1, L2) with arbitrary rows for L1, L2.
  LawOutput out;
  const int n = 6;
  for (int j = 0; j < n; ++j) {
    out.J[4 * n + j] = 1.0 + j;
    out.J[5 * n + j] = 10.0 - j;
  }
  out.r[4] = 0.5, out.r[5] = -0.25;
  PrescribedSlip s;  // t1 free, t2 prescribed
  s.prescribed = 1;
  const double w = 2.0;
  dropPrescribedFriction(s, 2, w, {0.3, 0.7}, n, out);
  EXPECT_DOUBLE_EQ(out.r[4], 0.5);  // the free row is untouched in the identity basis
  EXPECT_DOUBLE_EQ(out.J[4 * n + 2], 3.0);
  EXPECT_DOUBLE_EQ(out.r[5], w * 0.7);  // w Lambda_2
  for (int j = 0; j < n; ++j)
    EXPECT_DOUBLE_EQ(out.J[5 * n + j], j == 5 ? w : 0.0);
}

}  // namespace
}  // namespace contactlab
