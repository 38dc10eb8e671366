#pragma once
// Node-to-segment collocation (the seed's): each slave node is a contact point whose master is
// the closest point on the master surface (ContactSearch). The normal there is the nodal-averaged
// normal interpolated at that point (continuous across the kinks of a faceted, deformed surface,
// as Code_Aster's normal smoothing). With the geometry in Newton its pairing is linearized: the
// master point's motion on its facet (`pairing`) and also the smoothed normal, which depends on
// the master nodes of the facets around (`full`).
#include "formulations/ContactDiscretization.hpp"
#include "formulations/MasterSurface.hpp"

#include <map>
#include <memory>

namespace contactlab {

class NodeToSegmentDiscretization : public ContactDiscretization {
 public:
  NodeToSegmentDiscretization(const ContactZone& zone, const Mesh& mesh, int dim);

  std::vector<std::int64_t> masterNodes() const override { return master_.facetNodes(); }
  void prepare(const ContactSurfaceState& state, double t) override;
  PointPairing pair(ContactPoint& pt, const std::array<double, 3>& xs,
                    const ContactSurfaceState& state, double t) override;
  // The smoothed normal at the frozen master point (shape values N) from the nodal normals of
  // the facets around its master nodes at the current positions.
  std::array<double, 3> currentNormal(const ContactPoint& pt, const ContactSurfaceState& state,
                                      double t) const override;
  // In closed form (SmoothedNormalDerivative.hpp).
  bool currentNormalDerivative(
      const ContactPoint& pt, const ContactSurfaceState& state, double t,
      std::map<std::int64_t, std::array<double, 9>>& blocks) const override;
  bool linearizesGeometry() const override { return true; }
  bool fullTermsAddToPairing() const override { return true; }
  std::vector<std::int64_t> normalNodes(const ContactPoint& pt) const override;
  void refreshGeometry(ContactPoint& pt, const ContactSurfaceState& state, double t,
                       GeometricTerms terms) const override;

 private:
  // The current facets around the point's master nodes, and their nodes.
  void facetsAround(const ContactPoint& pt, const ContactSurfaceState& state,
                    std::vector<Facet>& facets, std::vector<std::int64_t>& facetNodes) const;
  // The nodal normals of the facets around the point's master nodes, at the state's positions.
  std::map<std::int64_t, std::array<double, 3>> nodalNormalsAround(
      const ContactPoint& pt, const ContactSurfaceState& state) const;
  // The smoothed normal at the point's master point, from its master nodes' normals and shape
  // values (fallback: the facet's own normal).
  std::array<double, 3> smoothedNormal(const ContactPoint& pt,
                                       const std::map<std::int64_t, std::array<double, 3>>& nodal,
                                       const double* facetNormal) const;

  MasterSurface master_;
  std::unique_ptr<ContactSearch> search_;  // at the last prepare()
  std::map<std::int64_t, std::array<double, 3>> nodalNormals_;
};

}  // namespace contactlab
