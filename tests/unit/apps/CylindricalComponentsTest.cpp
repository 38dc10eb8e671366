// Cylindrical components (apps/output/CylindricalComponents.hpp), which Output/Profiles writes
// for a tube's hoop stress: Lame's plane stress field of a pressurized ring, written in
// Cartesian components at a point of any angle, comes back as (sigma_r, sigma_t); an axis
// that is not z and does not pass through the origin; a vector; NaN on the axis.
#include "apps/output/CylindricalComponents.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

// sigma_r e_r e_r + sigma_t e_t e_t about z at angle theta, Voigt xx yy zz xy yz xz.
std::array<double, 6> polar(double sr, double st, double sz, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {sr * c * c + st * s * s, sr * s * s + st * c * c, sz, (sr - st) * c * s, 0, 0};
}

TEST(CylindricalComponents, ALameFieldComesBackAsRadialAndHoop) {
  for (double theta : {0.0, 0.3, 1.2, 2.5, -2.0}) {
    const double r = 1.7;
    const auto s = cylindricalComponents(polar(-3.0, 5.0, 0.6, theta),
                                         {r * std::cos(theta), r * std::sin(theta), 4.0}, {0, 0, 0},
                                         {0, 0, 2.0});
    EXPECT_NEAR(s[0], -3.0, 1e-12) << theta;
    EXPECT_NEAR(s[1], 5.0, 1e-12) << theta;
    EXPECT_NEAR(s[2], 0.6, 1e-12) << theta;
    for (int k = 3; k < 6; ++k)
      EXPECT_NEAR(s[k], 0.0, 1e-12) << theta << " " << k;
  }
}

TEST(CylindricalComponents, AnAxisAlongXThroughAnotherPoint) {
  // Axis x through (0, 1, 1); the point (5, 1, 3) is at r = 2 along +z, so e_r = z,
  // e_t = x cross z = -y, e_z = x.
  const std::array<double, 6> s{1, 2, 3, 4, 5, 6};  // xx yy zz xy yz xz
  const auto c = cylindricalComponents(s, {5, 1, 3}, {0, 1, 1}, {1, 0, 0});
  EXPECT_NEAR(c[0], 3, 1e-12);   // rr = zz
  EXPECT_NEAR(c[1], 2, 1e-12);   // tt = yy
  EXPECT_NEAR(c[2], 1, 1e-12);   // zz = xx
  EXPECT_NEAR(c[3], -5, 1e-12);  // rt = z.S.(-y) = -yz
  EXPECT_NEAR(c[4], -4, 1e-12);  // tz = (-y).S.x = -xy
  EXPECT_NEAR(c[5], 6, 1e-12);   // rz = z.S.x = xz
  const auto v =
      cylindricalComponents(std::array<double, 3>{1, 2, 3}, {5, 1, 3}, {0, 1, 1}, {1, 0, 0});
  EXPECT_NEAR(v[0], 3, 1e-12);
  EXPECT_NEAR(v[1], -2, 1e-12);
  EXPECT_NEAR(v[2], 1, 1e-12);
}

TEST(CylindricalComponents, OnTheAxisTheyAreUndefined) {
  const auto c = cylindricalComponents(std::array<double, 6>{1, 1, 1, 0, 0, 0}, {0, 0, 2},
                                       {0, 0, 0}, {0, 0, 1});
  EXPECT_TRUE(std::isnan(c[0]));
  EXPECT_TRUE(std::isnan(c[1]));
}

}  // namespace
}  // namespace contactlab
