#pragma once
// Which of the master facets overlapping a slave facet's projection are its contact partners.
//
// Mortar integrates a slave facet against every master facet whose projection along the slave
// normal covers part of it. The search only bounds the candidates by boxes, so a master surface
// behind the nearest one projects onto the slave as well (in a fir-tree blade root, the disc's
// next lobe behind the flank it touches), and weighted gaps that average the two surfaces open
// a closed contact. Node-to-segment takes the closest point; mortar keeps, per slave facet, the
// masters of the surface nearest to it:
//  - facing: the master's outward normal opposes the slave's (n_M . n_S < 0), else it is the
//    far side of the master body;
//  - within the search distance: the mean gap over the master's overlap, |g|, is at most the
//    zone's Search Distance ("master points farther than this from a slave point are ignored");
//  - one surface: of those, with g_ref the mean gap of the one nearest to the slave (smallest
//    |g|), a master whose mean gap is below g_ref - size (behind it by more than the slave
//    facet's size) belongs to another surface and is dropped. Masters in front are kept: an
//    open surface inclined across the slave spreads its gaps over more than the facet's size.
// g is (x_M - x_S) . n_S, positive where open.
#include "core/contact/MortarIntegration.hpp"

#include <vector>

namespace contactlab {

// One master facet's integrals against the slave, before the selection.
struct MasterOverlap {
  MortarMaster integrals;        // its M (ns x nm)
  std::vector<double> D;         // its share of D (ns x ns, standard basis)
  double area = 0.0;             // the slave area it covers
  double gapMoment = 0.0;        // int_overlap g dA
  double alignmentMoment = 0.0;  // int_overlap n_M . n_S dA (unit normals)
  double meanGap() const { return area > 0 ? gapMoment / area : 0.0; }
  bool facing() const { return alignmentMoment < 0; }
};

// Adds the selected overlaps' D, covered area and M (in the given order) to `out`. `size`: the
// slave facet's length scale; `searchDistance`: the zone's (HUGE_VAL: no bound).
void addNearestSurface(std::vector<MasterOverlap>& overlaps, double size, double searchDistance,
                       MortarIntegrals& out);

}  // namespace contactlab
