// Rigid analytic obstacles: known closest points, normals and gaps.
#include "core/contact/RigidObstacle.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

using Shape = RigidObstacleSpec::Shape;
using Side = RigidObstacleSpec::Side;

// An obstacle at rest on the outside: point, direction and radius as RigidObstacleSpec says.
RigidObstacleSpec spec(Shape shape, const std::array<double, 3>& point,
                       const std::array<double, 3>& direction, double radius = 0.0) {
  RigidObstacleSpec s;
  s.shape = shape;
  s.point = point;
  s.direction = direction;
  s.radius = radius;
  return s;
}

void expectNear(const std::array<double, 3>& a, const std::array<double, 3>& b, double tol) {
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(a[i], b[i], tol) << "component " << i;
}

TEST(RigidObstacle, TiltedPlaneGapNormalAndClosestPoint) {
  // The normal (3, 4, 0) is normalized to (0.6, 0.8, 0).
  RigidObstacle plane(spec(Shape::Plane, {1, 0, 0}, {3, 4, 0}), 3);
  const double x[3] = {1 + 0.6 * 2, 0.8 * 2, 5};  // 2 above the plane
  const auto p = plane.project(x, 0.0);
  EXPECT_NEAR(p.gap, 2.0, 1e-14);
  expectNear(p.normal, {0.6, 0.8, 0}, 1e-15);
  expectNear(p.point, {1, 0, 5}, 1e-14);
  const double below[3] = {1 - 0.6, -0.8, 0};
  EXPECT_NEAR(plane.project(below, 0.0).gap, -1.0, 1e-14);
}

TEST(RigidObstacle, TranslationFollowsItsLoadFunction) {
  RigidObstacleSpec s;
  s.direction = {0, 1, 0};
  s.displacement = {0, 0.5, 0};
  s.function.endTime = 2.0;
  RigidObstacle ramp(s, 2);
  const double x[3] = {0, 1, 0};
  EXPECT_NEAR(ramp.project(x, 1.0).gap, 0.75, 1e-15);  // moved by 0.25 at t = 1 of 2
  expectNear(ramp.translation(2.0), {0, 0.5, 0}, 1e-15);
  s.function.kind = LoadFunction::Kind::Constant;
  EXPECT_NEAR(RigidObstacle(s, 2).project(x, 0.0).gap, 0.5, 1e-15);
  s.function = LoadFunction{};
  s.function.startTime = 0.5;  // sequenced: still at t = 0.5, halfway at 0.75
  EXPECT_NEAR(RigidObstacle(s, 2).project(x, 0.5).gap, 1.0, 1e-15);
  EXPECT_NEAR(RigidObstacle(s, 2).project(x, 0.75).gap, 0.75, 1e-15);
}

TEST(RigidObstacle, SphereOutsideAndInside) {
  RigidObstacleSpec s = spec(Shape::Sphere, {1, 1, 1}, {}, 2);
  const double x[3] = {1, 1, 4};  // 3 above the centre
  const auto out = RigidObstacle(s, 3).project(x, 0.0);
  EXPECT_NEAR(out.gap, 1.0, 1e-15);
  expectNear(out.normal, {0, 0, 1}, 1e-15);
  expectNear(out.point, {1, 1, 3}, 1e-15);
  s.side = Side::Inside;  // a spherical cavity: the body is inside
  const double in[3] = {1, 1, 2.5};
  const auto hole = RigidObstacle(s, 3).project(in, 0.0);
  EXPECT_NEAR(hole.gap, 0.5, 1e-15);
  expectNear(hole.normal, {0, 0, -1}, 1e-15);
  expectNear(hole.point, {1, 1, 3}, 1e-15);
}

TEST(RigidObstacle, ObliqueCylinderAndTwoDimensionalCircle) {
  // A point 2 from the axis along (0, 0, 1), anywhere along the axis.
  const double x[3] = {3, 3, 2};
  const auto p = RigidObstacle(spec(Shape::Cylinder, {0, 0, 0}, {1, 1, 0}, 1), 3).project(x, 0.0);
  EXPECT_NEAR(p.gap, 1.0, 1e-14);
  expectNear(p.normal, {0, 0, 1}, 1e-14);
  expectNear(p.point, {3, 3, 1}, 1e-14);
  RigidObstacleSpec c = spec(Shape::Cylinder, {1, 0, 0}, {0, 0, 1}, 0.5);
  const double q[3] = {1, 2, 0};
  const auto circle = RigidObstacle(c, 2).project(q, 0.0);
  EXPECT_NEAR(circle.gap, 1.5, 1e-15);
  expectNear(circle.normal, {0, 1, 0}, 1e-15);
  c.shape = Shape::Sphere;  // a sphere is the same circle in 2D
  EXPECT_NEAR(RigidObstacle(c, 2).project(q, 0.0).gap, 1.5, 1e-15);
}

TEST(RigidObstacle, PointAtTheCentreStaysFinite) {
  const double centre[3] = {0, 0, 0};
  const auto p = RigidObstacle(spec(Shape::Sphere, {0, 0, 0}, {}, 1), 3).project(centre, 0.0);
  EXPECT_NEAR(p.gap, -1.0, 1e-15);
  EXPECT_NEAR(std::hypot(p.normal[0], p.normal[1], p.normal[2]), 1.0, 1e-15);
}

TEST(RigidObstacle, BadSpecificationsAreNamed) {
  RigidObstacleSpec plane;  // zero normal
  EXPECT_THROW(RigidObstacle(plane, 3), std::invalid_argument);
  RigidObstacleSpec sphere;
  sphere.shape = Shape::Sphere;  // radius 0
  EXPECT_THROW(RigidObstacle(sphere, 3), std::invalid_argument);
  RigidObstacleSpec cylinder;
  cylinder.shape = Shape::Cylinder;
  cylinder.radius = 1;
  cylinder.direction = {1, 0, 0};  // 2D needs axis z
  EXPECT_THROW(RigidObstacle(cylinder, 2), std::invalid_argument);
  cylinder.direction = {0, 0, 1};
  EXPECT_NO_THROW(RigidObstacle(cylinder, 2));
  EXPECT_THROW(RigidObstacle(cylinder, 4), std::invalid_argument);
}

}  // namespace
}  // namespace contactlab
