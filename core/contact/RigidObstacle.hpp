#pragma once
// Rigid analytic master surfaces: a plane, a sphere or a cylinder, translated rigidly by a
// prescribed displacement scaled by a load function of time. In 2D (plane strain, z ignored) a
// sphere and a cylinder with axis z are both a circle.
//
// `Side` says where the body is: `outside` (an indenter, a punch: the body is outside the
// sphere or cylinder) or `inside` (a hole, a bore: the body is inside). A plane's body side is
// the one its normal points to.
#include "core/problem/Loads.hpp"

#include <array>
#include <string>

namespace contactlab {

struct RigidObstacleSpec {
  enum class Shape { Plane, Sphere, Cylinder };
  enum class Side { Outside, Inside };
  Shape shape = Shape::Plane;
  Side side = Side::Outside;
  std::array<double, 3> point{};         // plane: a point on it; sphere: centre; cylinder: on axis
  std::array<double, 3> direction{};     // plane: normal towards the body; cylinder: axis
  double radius = 0.0;                   // sphere and cylinder
  std::array<double, 3> displacement{};  // rigid translation at the end of the load
  LoadFunction function;                 // scales `displacement` with time
};

// Closest point of the obstacle to a point x, the unit normal there pointing towards the
// body's side, and the signed gap (x - point) . normal (> 0: apart, < 0: penetrating).
struct ObstacleProjection {
  std::array<double, 3> point{};
  std::array<double, 3> normal{};
  double gap = 0.0;
};

class RigidObstacle {
 public:
  // spaceDim 2 or 3. Throws std::invalid_argument for a zero normal/axis, a radius <= 0 on a
  // sphere or cylinder, or (2D) a cylinder whose axis is not z.
  RigidObstacle(const RigidObstacleSpec& spec, int spaceDim);

  // Projection of x (3 components; z = 0 in 2D) at time t. A point on the axis or at the
  // centre (normal undefined) gets the normal of the first coordinate axis orthogonal to the
  // cylinder axis, so the result is always finite.
  ObstacleProjection project(const double* x, double t) const;
  // project(), its point taken back by the translation at t (where it sits on the obstacle at
  // rest): what a contact point keeps of its pairing.
  ObstacleProjection projectAtRest(const double* x, double t) const;
  // Rigid translation of the obstacle at time t.
  std::array<double, 3> translation(double t) const;
  // The obstacle's side of a contact point's kinematics: subtracts `pointAtRest` translated to
  // time t from `relative`, and the translation since tConverged from `slip`.
  void subtractFrom(const std::array<double, 3>& pointAtRest, double t, double tConverged,
                    std::array<double, 3>& relative, std::array<double, 3>& slip) const;
  const RigidObstacleSpec& spec() const { return spec_; }

 private:
  RigidObstacleSpec spec_;  // direction normalized
  int spaceDim_;
};

}  // namespace contactlab
