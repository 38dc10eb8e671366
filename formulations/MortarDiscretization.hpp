#pragma once
// Mortar: each slave node j is a point with gap n_j . (sum_k D_jk x_k - sum_l M_jl x_l) / w_j,
// w_j = sum_k D_jk, n_j the slave's nodal normal (turned towards the slave), D and M integrated
// over the current slave facets around j (integrateMortar) at each pairing; the slip likewise
// with the increments. The point's weight is w_j times its facets' reference-to-current area
// ratio, so that its multiplier is a pressure per reference area as node-to-segment's is. Its
// geometry is a fixed point: no geometric terms (the segmentation's derivatives are not
// linearized), whatever Algorithm/Geometric Terms says.
#include "formulations/ContactDiscretization.hpp"
#include "formulations/MasterSurface.hpp"

#include <map>
#include <string>

namespace contactlab {

class MortarDiscretization : public ContactDiscretization {
 public:
  MortarDiscretization(const ContactZone& zone, const Mesh& mesh, int dim);

  std::vector<std::int64_t> masterNodes() const override { return master_.facetNodes(); }
  void prepare(const ContactSurfaceState& state, double t) override;
  PointPairing pair(ContactPoint& pt, const std::array<double, 3>& xs,
                    const ContactSurfaceState& state, double t) override;

 private:
  // A point's row: sum_k D_jk x_k - sum_l M_jl x_l over the slave facets around slave node j,
  // and the slave's nodal normal there.
  struct Row {
    std::map<std::int64_t, double> slave, master;
    std::array<double, 3> normal{};
    bool quadratic = false;  // on quadratic slave facets
  };
  // The rows of the slave nodes at the current positions (the slave facets against the master
  // facets `search` finds within the search distance).
  std::map<std::int64_t, Row> rows(const ContactSearch& search,
                                   const ContactSurfaceState& state) const;

  const Mesh& mesh_;
  std::string zoneName_, slave_;
  MultiplierBasis basis_;
  SurfaceWeight areaWeight_;  // the zone's (ContactZone::areaWeight)
  MasterSurface master_;
  std::map<std::int64_t, Row> rows_;             // at the last prepare()
  std::map<std::int64_t, double> currentAreas_;  // tributary areas at the last prepare()
};

}  // namespace contactlab
