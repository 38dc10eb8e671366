#pragma once
// A slave surface against a rigid obstacle (plane, sphere, cylinder, moving by a prescribed
// translation): each slave node is a point paired with its projection on the obstacle, paired
// while closer than the search distance. With the geometry in Newton the projection's motion
// (point and normal) enters the tangent.
#include "core/contact/RigidObstacle.hpp"
#include "formulations/ContactDiscretization.hpp"

namespace contactlab {

class ObstacleDiscretization : public ContactDiscretization {
 public:
  ObstacleDiscretization(const ContactZone& zone, const Mesh& mesh, int dim);

  PointPairing pair(ContactPoint& pt, const std::array<double, 3>& xs,
                    const ContactSurfaceState& state, double t) override;
  std::array<double, 3> masterPoint(const ContactPoint& pt, const std::array<double, 3>& xs,
                                    const ContactSurfaceState& state) const override;
  void subtractMasterSide(const ContactPoint& pt, const ContactSurfaceState& state, double t,
                          double tConverged, std::array<double, 3>& relative,
                          std::array<double, 3>& slip) const override;
  // The obstacle's normal at the projection of the slave's current position.
  std::array<double, 3> currentNormal(const ContactPoint& pt, const ContactSurfaceState& state,
                                      double t) const override;
  // Taken by differences: the obstacle's normal at the slave's projection (cheap, slave dofs only).
  bool currentNormalDerivative(const ContactPoint&, const ContactSurfaceState&, double,
                               std::map<std::int64_t, std::array<double, 9>>&) const override {
    return false;
  }
  bool linearizesGeometry() const override { return true; }
  void refreshGeometry(ContactPoint& pt, const ContactSurfaceState& state, double t,
                       GeometricTerms terms) const override;

 private:
  // The obstacle's normal and point (without its translation) for a slave at xs; the gap.
  double place(ContactPoint& pt, const std::array<double, 3>& xs, double t) const;

  RigidObstacle obstacle_;
};

}  // namespace contactlab
