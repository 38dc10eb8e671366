#pragma once
// What a converged contact state carries into the next step beyond the displacements, per
// contact point in ContactProblem's point order (the same on any number of ranks): the
// formulation's point unknowns (multipliers p, Lambda; a normal field's n), the Coulomb law's
// history (the tangential resistance of the last converged step and the slip accumulated since
// the start), the pairing's master facet (node-to-segment keeps it at a tie: hysteresis) and the
// point's tangent frame.
// Checkpoints carry it (apps/RunCheckpoint); ContactProblem gets and sets it.
#include <cstdint>
#include <vector>

namespace contactlab {

struct ContactHistory {
  std::vector<std::int64_t> zone, node;      // per point: zone index, slave node (mesh index)
  std::vector<std::int64_t> unknownOffsets;  // per point + 1, into `unknowns`
  std::vector<double> unknowns;
  std::vector<double> resistance, slip;  // 3 per point
  std::vector<std::int64_t> facet;       // per point: the paired master facet (-1: unpaired)
  // 3 per point: its tangent frame's t1, the frame its tangential unknowns are in (a frame keeps
  // its axis across updates, tangentBasisFollowing). Empty: a checkpoint written before frames
  // were kept; the points then take a first frame.
  std::vector<double> frame;
  bool everInContact = false;
};

}  // namespace contactlab
