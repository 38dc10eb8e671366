#pragma once
// The pairing stage of the contact pipeline (pairs -> points -> kinematics -> law -> assembly):
// where a zone's contact conditions are collocated and against what. A discretization turns the
// current configuration into paired contact points, each with its frozen geometry (master nodes
// and coefficients, normal), gives the kinematics the master side of each point, and, for the
// geometry in Newton, recomputes a point's geometry at perturbed positions. One class per
// discretization and target (ContactDiscretizationType.hpp builds them):
//   node-to-segment  NodeToSegmentDiscretization   a slave node against its closest master point
//                    ObstacleDiscretization        a slave node against an analytic surface
//   mortar           MortarDiscretization          weighted over the slave facets (D and M)
//                    ObstacleMortarDiscretization  mortar's weighted gaps against an obstacle
#include "core/mesh/Mesh.hpp"
#include "formulations/ContactControls.hpp"
#include "formulations/ContactPoint.hpp"
#include "formulations/ContactSurfaceState.hpp"
#include "formulations/ContactZone.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace contactlab {

// What pairing one point found, beside what it stored in the point.
struct PointPairing {
  double gap = 0;   // > 0 apart, along the frozen normal
  double size = 0;  // the master facet's size (the initial-penetration check)
};

class ContactDiscretization {
 public:
  ContactDiscretization(int dim, double searchDistance)
      : dim_(dim), searchDistance_(searchDistance) {}
  virtual ~ContactDiscretization() = default;

  // Master facets farther than this from a slave point are not candidates; an unpaired point's
  // gap.
  double searchDistance() const { return searchDistance_; }
  // The master nodes whose motion enters the points' geometry (the surface state holds them).
  virtual std::vector<std::int64_t> masterNodes() const { return {}; }
  // Once per pairing, before pair(): what the points share at the current state (the master
  // surface's search tree, normals, the mortar integrals).
  virtual void prepare(const ContactSurfaceState& /*state*/, double /*t*/) {}
  // Pairs one point whose slave is at xs: sets its `paired`, and when paired its master nodes
  // and coefficients, `self`, `facet`, `normal` (and `weight` for mortar). The point still holds
  // its previous pairing on entry (for hysteresis).
  virtual PointPairing pair(ContactPoint& pt, const std::array<double, 3>& xs,
                            const ContactSurfaceState& state, double t) = 0;
  // The master side the slave at xs is paired with: x_s - masterPoint = self x_s - sum_a N_a x_a
  // (an obstacle: its point, without its translation). For telling whether a pairing moved.
  virtual std::array<double, 3> masterPoint(const ContactPoint& pt, const std::array<double, 3>& xs,
                                            const ContactSurfaceState& state) const;
  // Kinematics: subtracts the master side's position from `relative` (self x_s on entry) and its
  // increment since the converged step (at tConverged) from `slip` (self (u_s - u_s^conv)).
  virtual void subtractMasterSide(const ContactPoint& pt, const ContactSurfaceState& state,
                                  double t, double tConverged, std::array<double, 3>& relative,
                                  std::array<double, 3>& slip) const;

  // The master's normal at the point's frozen master point, at the state's positions (the
  // normal-field formulation's n(u)); by default the pairing's normal.
  virtual std::array<double, 3> currentNormal(const ContactPoint& pt,
                                              const ContactSurfaceState& /*state*/,
                                              double /*t*/) const {
    return pt.normal;
  }
  // Its derivative in closed form, dn_i/dx_(b,j) at [i * 3 + j] for each node b it depends on
  // (none: a constant normal). False when this discretization has none: the kernel then takes
  // central differences of currentNormal.
  virtual bool currentNormalDerivative(
      const ContactPoint& /*pt*/, const ContactSurfaceState& /*state*/, double /*t*/,
      std::map<std::int64_t, std::array<double, 9>>& blocks) const {
    blocks.clear();
    return true;
  }

  // The geometry in Newton. Whether this discretization's pairing has derivatives in the tangent
  // (finite differences of refreshGeometry); the nodes, beyond the point's own, its normal
  // depends on with `full` terms; and the point's geometry recomputed at the state's positions.
  virtual bool linearizesGeometry() const { return false; }
  // Whether `full` terms add to `pairing` ones here: a normal that turns with other nodes than
  // the point's own (a node-to-segment master's smoothed normal; an obstacle's follows the
  // slave alone, in `pairing` already).
  virtual bool fullTermsAddToPairing() const { return false; }
  virtual std::vector<std::int64_t> normalNodes(const ContactPoint& /*pt*/) const { return {}; }
  virtual void refreshGeometry(ContactPoint& /*pt*/, const ContactSurfaceState& /*state*/,
                               double /*t*/, GeometricTerms /*terms*/) const {}

 protected:
  int dim_;
  double searchDistance_;
};

// A key of a point's coupled nodes (FNV-1a of `nodes`, in [0, 2^30)): a new key, a new pairing
// and so a new graph (the mortar discretizations' ContactPoint::facet).
int couplingKey(const std::vector<std::int64_t>& nodes);
// The zone's search distance: its own, or automatic: twice the largest slave facet (a slave
// point moves less than that in a step of a reasonable load history).
double resolvedSearchDistance(const ContactZone& zone, const Mesh& mesh);

}  // namespace contactlab
