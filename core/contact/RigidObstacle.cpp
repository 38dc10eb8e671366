#include "core/contact/RigidObstacle.hpp"

#include <cmath>
#include <stdexcept>

namespace contactlab {
namespace {

double norm3(const std::array<double, 3>& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

}  // namespace

RigidObstacle::RigidObstacle(const RigidObstacleSpec& spec, int spaceDim)
    : spec_(spec), spaceDim_(spaceDim) {
  using Shape = RigidObstacleSpec::Shape;
  if (spaceDim != 2 && spaceDim != 3)
    throw std::invalid_argument("rigid obstacle: the space dimension must be 2 or 3");
  if (spaceDim == 2) {  // plane strain lives in z = 0; only a cylinder's axis points out of it
    spec_.point[2] = 0.0;
    if (spec.shape != Shape::Cylinder) spec_.direction[2] = 0.0;
  }
  if (spec_.shape != Shape::Sphere) {
    const double n = norm3(spec_.direction);
    if (!(n > 0))
      throw std::invalid_argument(spec_.shape == Shape::Plane
                                      ? "rigid plane: the Normal must be a nonzero vector"
                                      : "rigid cylinder: the Axis must be a nonzero vector");
    for (double& v : spec_.direction)
      v /= n;
  }
  if (spec_.shape != Shape::Plane && !(spec_.radius > 0))
    throw std::invalid_argument("rigid sphere or cylinder: the Radius must be > 0");
  if (spaceDim == 2 && spec_.shape == Shape::Cylinder &&
      (std::abs(spec_.direction[0]) > 1e-12 || std::abs(spec_.direction[1]) > 1e-12))
    throw std::invalid_argument("rigid cylinder in 2D: the Axis must be z (0, 0, 1)");
}

std::array<double, 3> RigidObstacle::translation(double t) const {
  const double f = spec_.function(t);
  return {spec_.displacement[0] * f, spec_.displacement[1] * f,
          spaceDim_ == 3 ? spec_.displacement[2] * f : 0.0};
}

ObstacleProjection RigidObstacle::projectAtRest(const double* x, double t) const {
  ObstacleProjection p = project(x, t);
  const auto shift = translation(t);
  for (int c = 0; c < 3; ++c)
    p.point[c] -= shift[c];
  return p;
}

void RigidObstacle::subtractFrom(const std::array<double, 3>& pointAtRest, double t,
                                 double tConverged, std::array<double, 3>& relative,
                                 std::array<double, 3>& slip) const {
  const auto now = translation(t);
  const auto then = translation(tConverged);
  for (int c = 0; c < 3; ++c) {
    relative[c] -= pointAtRest[c] + now[c];
    slip[c] -= now[c] - then[c];
  }
}

ObstacleProjection RigidObstacle::project(const double* x, double t) const {
  using Shape = RigidObstacleSpec::Shape;
  const auto shift = translation(t);
  std::array<double, 3> r{};  // from the (moved) reference point to x
  for (int i = 0; i < 3; ++i)
    r[i] = (i < spaceDim_ ? x[i] : 0.0) - spec_.point[i] - shift[i];
  ObstacleProjection p;
  if (spec_.shape == Shape::Plane) {
    const auto& n = spec_.direction;
    p.gap = r[0] * n[0] + r[1] * n[1] + r[2] * n[2];
    p.normal = n;
    for (int i = 0; i < 3; ++i)
      p.point[i] = (i < spaceDim_ ? x[i] : 0.0) - p.gap * n[i];
    return p;
  }
  // Sphere (a circle in 2D) or cylinder: the radial part of r.
  std::array<double, 3> radial = r;
  std::array<double, 3> axis{0, 0, 1};
  if (spec_.shape == Shape::Cylinder) axis = spec_.direction;
  if (spec_.shape == Shape::Cylinder || spaceDim_ == 2) {
    const double along = r[0] * axis[0] + r[1] * axis[1] + r[2] * axis[2];
    for (int i = 0; i < 3; ++i)
      radial[i] -= along * axis[i];
  }
  double distance = norm3(radial);
  if (!(distance > 0)) {
    // At the centre or on the axis: any radial direction; the first axis not along `axis`.
    int i = std::abs(axis[0]) < 0.9 ? 0 : 1;
    radial = {0, 0, 0};
    radial[i] = 1.0;
    const double along = radial[0] * axis[0] + radial[1] * axis[1] + radial[2] * axis[2];
    for (int k = 0; k < 3; ++k)
      radial[k] -= along * axis[k];
    const double n = norm3(radial);
    for (double& v : radial)
      v /= n;
    distance = 0.0;
  } else {
    for (double& v : radial)
      v /= distance;
  }
  const bool outside = spec_.side == RigidObstacleSpec::Side::Outside;
  for (int i = 0; i < 3; ++i) {
    p.normal[i] = outside ? radial[i] : -radial[i];
    p.point[i] = (i < spaceDim_ ? x[i] : 0.0) + (spec_.radius - distance) * radial[i];
  }
  p.gap = outside ? distance - spec_.radius : spec_.radius - distance;
  return p;
}

}  // namespace contactlab
