#pragma once
// Mortar against a rigid obstacle: each slave node j is a point whose gap is the weighted gap
// int_S Phi_j g dA / w_j over the slave facets around it, w_j = int_S Phi_j dA, with the
// multiplier basis Phi of mortar (dual or standard; on tri6 and quad8 built on the transformed
// functions whose corner integrals are positive). An obstacle covers every facet, so D_jk =
// int_S Phi_j N_k dA is the whole facets' (integrateWholeFacet), and for a plane the weighted
// gap is the gap of the point x_j = sum_k D_jk x_k / w_j: self = D_jj / w_j and the other
// slave nodes as `master` with N = -D_jk / w_j, along the obstacle's normal at x_j. On a curved
// obstacle the weighted gap, integrated at the facets' quadrature points, is the point's gap at
// the pairing (its obstacle point is placed so); Newton moves it along that normal, as it does
// node-to-segment's between pairings. On linear facets with the dual basis D is diagonal and
// this is node-to-segment's
// obstacle pairing with its lumped areas. Why: node-to-segment collocates at tri6 and quad8
// corners that carry no share of a smooth pressure; against a meshed master mortar is the sound
// choice, and this makes it one against an obstacle too (doc/verification.md). Its geometry is
// a fixed point, as mortar's: no geometric terms.
#include "core/contact/MortarIntegration.hpp"
#include "core/contact/RigidObstacle.hpp"
#include "formulations/ContactDiscretization.hpp"

#include <map>
#include <string>

namespace contactlab {

class ObstacleMortarDiscretization : public ContactDiscretization {
 public:
  ObstacleMortarDiscretization(const ContactZone& zone, const Mesh& mesh, int dim);

  void prepare(const ContactSurfaceState& state, double t) override;
  PointPairing pair(ContactPoint& pt, const std::array<double, 3>& xs,
                    const ContactSurfaceState& state, double t) override;
  std::array<double, 3> masterPoint(const ContactPoint& pt, const std::array<double, 3>& xs,
                                    const ContactSurfaceState& state) const override;
  void subtractMasterSide(const ContactPoint& pt, const ContactSurfaceState& state, double t,
                          double tConverged, std::array<double, 3>& relative,
                          std::array<double, 3>& slip) const override;
  // The obstacle's normal at the projection of the point's weighted position x_j.
  std::array<double, 3> currentNormal(const ContactPoint& pt, const ContactSurfaceState& state,
                                      double t) const override;

 private:
  // x_j = self x_s - sum_a N_a x_a at the state's positions.
  std::array<double, 3> weightedPosition(const ContactPoint& pt,
                                         const ContactSurfaceState& state) const;

  const Mesh& mesh_;
  std::string zoneName_, slave_;
  MultiplierBasis basis_;
  SurfaceWeight areaWeight_;
  RigidObstacle obstacle_;
  // A slave node's D_jk and weighted gap int Phi_j g dA, summed over its facets.
  struct Row {
    std::map<std::int64_t, double> D;
    double gap = 0.0;
  };
  std::map<std::int64_t, Row> rows_;             // at the last prepare()
  std::map<std::int64_t, double> currentAreas_;  // tributary areas at the last prepare()
};

}  // namespace contactlab
