#include "core/contact/MortarMasterSelection.hpp"

#include <cmath>
#include <cstddef>

namespace contactlab {

void addNearestSurface(std::vector<MasterOverlap>& overlaps, double size, double searchDistance,
                       MortarIntegrals& out) {
  const auto candidate = [searchDistance](const MasterOverlap& o) {
    return o.area > 0 && o.facing() && std::abs(o.meanGap()) <= searchDistance;
  };
  double reference = HUGE_VAL;
  for (const MasterOverlap& o : overlaps)
    if (candidate(o) && std::abs(o.meanGap()) < std::abs(reference)) reference = o.meanGap();
  for (MasterOverlap& o : overlaps) {
    if (!candidate(o) || o.meanGap() < reference - size) continue;
    for (std::size_t i = 0; i < out.D.size(); ++i)
      out.D[i] += o.D[i];
    out.coveredArea += o.area;
    out.masters.push_back(std::move(o.integrals));
  }
}

}  // namespace contactlab
