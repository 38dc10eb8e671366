// ContactProblem's checkpoint hooks: the contact state a converged step leaves for the next.
#include "base/InputError.hpp"
#include "formulations/ContactPoint.hpp"
#include "formulations/ContactPointKernel.hpp"
#include "formulations/ContactProblem.hpp"
#include "formulations/ContactSurfaceState.hpp"

namespace contactlab {

std::vector<double> ContactProblem::pointUnknowns(const Vector& v) {
  state_->import(v);  // every multiplier on every rank
  const auto values = state_->values();
  std::vector<double> unknowns;
  for (const ContactPoint& pt : points_)
    for (int j = 0; pt.multiplier >= 0 && j < pt.unknowns; ++j)
      unknowns.push_back(values[state_->multiplierPosition(pt.multiplier + j)]);
  return unknowns;
}

void ContactProblem::setPointUnknowns(const std::vector<double>& unknowns, Vector& v) const {
  std::size_t expected = 0;
  for (const ContactPoint& pt : points_)
    expected += pt.multiplier >= 0 ? pt.unknowns : 0;
  if (unknowns.size() != expected)
    throw InputError("the checkpoint has " + std::to_string(unknowns.size()) +
                     " contact point unknowns, this scene's contact zones " +
                     std::to_string(expected));
  auto values = v.getDataNonConst(0);
  std::size_t k = 0;
  for (const ContactPoint& pt : points_)
    for (int j = 0; pt.multiplier >= 0 && j < pt.unknowns; ++j, ++k) {
      const LO lid = map_->getLocalElement(pt.multiplier + j);
      if (lid != Teuchos::OrdinalTraits<LO>::invalid()) values[lid] = unknowns[k];
    }
}

ContactHistory ContactProblem::convergedHistory(const Vector& x) {
  ContactHistory h;
  h.unknowns = pointUnknowns(x);
  h.unknownOffsets.push_back(0);
  std::int64_t offset = 0;
  for (const ContactPoint& pt : points_) {
    h.zone.push_back(pt.zone);
    h.node.push_back(pt.node);
    offset += pt.multiplier >= 0 ? pt.unknowns : 0;
    h.unknownOffsets.push_back(offset);
    h.resistance.insert(h.resistance.end(), pt.resistanceOld.begin(), pt.resistanceOld.end());
    h.slip.insert(h.slip.end(), pt.slipTotal.begin(), pt.slipTotal.end());
    h.facet.push_back(pt.paired ? pt.facet : -1);
    h.frame.insert(h.frame.end(), pt.t1.begin(), pt.t1.end());
  }
  h.everInContact = everInContact_;
  return h;
}

void ContactProblem::restoreHistory(const ContactHistory& h, Vector& x, double t) {
  // The history arrives whole on every rank, so every rank finds the same mismatch.
  const std::size_t n = points_.size();
  if (h.node.size() != n || h.zone.size() != n || h.unknownOffsets.size() != n + 1 ||
      h.resistance.size() != 3 * n || h.slip.size() != 3 * n || h.facet.size() != n ||
      (!h.frame.empty() && h.frame.size() != 3 * n))
    throw InputError("the checkpoint has " + std::to_string(h.node.size()) +
                     " contact points, this scene's contact zones " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i) {
    const ContactPoint& pt = points_[i];
    const int unknowns = pt.multiplier >= 0 ? pt.unknowns : 0;
    if (h.node[i] != pt.node || h.zone[i] != pt.zone ||
        h.unknownOffsets[i + 1] - h.unknownOffsets[i] != unknowns)
      throw InputError("the checkpoint's contact point " + std::to_string(i) + " (zone " +
                       std::to_string(h.zone[i]) + ", node index " + std::to_string(h.node[i]) +
                       ") is not this scene's (another contact zone or formulation)");
  }
  setPointUnknowns(h.unknowns, x);
  for (std::size_t i = 0; i < n; ++i) {
    ContactPoint& pt = points_[i];
    for (int c = 0; c < 3; ++c) {
      pt.resistanceOld[c] = h.resistance[3 * i + c];
      pt.slipTotal[c] = h.slip[3 * i + c];
      if (!h.frame.empty()) pt.t1[c] = h.frame[3 * i + c];
    }
    pt.slipIncrement = {0, 0, 0};
    pt.result.slip = pt.slipTotal;
    pt.paired = h.facet[i] >= 0;
    pt.facet = static_cast<int>(h.facet[i]);
  }
  // The graph was built for the pairing made before this (at rest): the next pairing keeps the
  // restored facets, which it would not see as a change, so the graph is rebuilt then.
  layoutChanged_ = true;
  state_->import(x);
  state_->commit();
  kernel_->setConvergedTime(t);
  everInContact_ = h.everInContact;
}

}  // namespace contactlab
