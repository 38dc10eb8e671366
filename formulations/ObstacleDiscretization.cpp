#include "formulations/ObstacleDiscretization.hpp"

#include "core/contact/SurfaceFrames.hpp"

namespace contactlab {

ObstacleDiscretization::ObstacleDiscretization(const ContactZone& zone, const Mesh& mesh, int dim)
    : ContactDiscretization(dim, resolvedSearchDistance(zone, mesh)),
      obstacle_(*zone.obstacle, dim) {}

double ObstacleDiscretization::place(ContactPoint& pt, const std::array<double, 3>& xs,
                                     double t) const {
  const ObstacleProjection proj = obstacle_.projectAtRest(xs.data(), t);
  pt.normal = proj.normal;
  pt.obstaclePoint = proj.point;
  return proj.gap;
}

PointPairing ObstacleDiscretization::pair(ContactPoint& pt, const std::array<double, 3>& xs,
                                          const ContactSurfaceState& /*state*/, double t) {
  PointPairing result;
  result.size = searchDistance_ / 2;
  result.gap = place(pt, xs, t);
  pt.paired = result.gap < searchDistance_;
  return result;
}

std::array<double, 3> ObstacleDiscretization::masterPoint(
    const ContactPoint& pt, const std::array<double, 3>& /*xs*/,
    const ContactSurfaceState& /*state*/) const {
  return pt.obstaclePoint;
}

void ObstacleDiscretization::subtractMasterSide(const ContactPoint& pt,
                                                const ContactSurfaceState& /*state*/, double t,
                                                double tConverged, std::array<double, 3>& relative,
                                                std::array<double, 3>& slip) const {
  obstacle_.subtractFrom(pt.obstaclePoint, t, tConverged, relative, slip);
}

std::array<double, 3> ObstacleDiscretization::currentNormal(const ContactPoint& pt,
                                                            const ContactSurfaceState& state,
                                                            double t) const {
  const auto xs = state.position(pt.node);
  return obstacle_.project(xs.data(), t).normal;
}

void ObstacleDiscretization::refreshGeometry(ContactPoint& pt, const ContactSurfaceState& state,
                                             double t, GeometricTerms /*terms*/) const {
  place(pt, state.position(pt.node), t);
  tangentBasisFollowing(dim_, pt.normal, pt.t1, pt.t2);
}

}  // namespace contactlab
