#include "algorithms/CyclingDetector.hpp"

#include <cmath>

namespace contactlab {

const char* cyclingKindName(CyclingKind kind) {
  switch (kind) {
    case CyclingKind::None:
      return "none";
    case CyclingKind::SubCycling1:
      return "sub-cycling-1";
    case CyclingKind::SubCycling2:
      return "sub-cycling-2";
    case CyclingKind::Grazing:
      return "grazing";
    case CyclingKind::ContactFlipFlop:
      return "contact-flip-flop";
    case CyclingKind::StickSlip:
      return "stick-slip";
    case CyclingKind::SlipReversal:
      return "slip-reversal";
  }
  return "?";
}

void CyclingDetector::reset() {
  histories_.clear();
}

void CyclingDetector::forget(std::size_t point) {
  if (point < histories_.size()) histories_[point] = History{};
}

std::vector<CyclingEvent> CyclingDetector::observe(const std::vector<ContactPointState>& states) {
  if (histories_.size() != states.size()) histories_.assign(states.size(), History{});
  std::vector<CyclingEvent> events;
  for (std::size_t i = 0; i < states.size(); ++i) {
    const ContactPointState& s = states[i];
    History& h = histories_[i];
    // Slip direction: a reversal is a friction direction that turns by more than 90 degrees
    // between two evaluations where the point slips.
    bool reversed = false;
    if (s.status == 2) {
      const double norm = std::sqrt(s.traction[0] * s.traction[0] + s.traction[1] * s.traction[1] +
                                    s.traction[2] * s.traction[2]);
      if (norm > 0) {
        std::array<double, 3> d{s.traction[0] / norm, s.traction[1] / norm, s.traction[2] / norm};
        if (h.slipping) {
          const double c = d[0] * h.lastSlipDirection[0] + d[1] * h.lastSlipDirection[1] +
                           d[2] * h.lastSlipDirection[2];
          if (c < 0) reversed = true;
        }
        h.lastSlipDirection = d;
        h.slipping = true;
      }
    } else {
      h.slipping = false;
    }
    h.reversals = reversed ? h.reversals + 1 : 0;
    if (h.reversals == 2) events.push_back({i, CyclingKind::SlipReversal});

    // Entries differ by the contact status (open zones 1, 2 or closed 3, 4) and the friction
    // status; within one, only the latest zone and gap are kept (a closed point's gap sits at
    // zero up to round-off, so its zone may flip between 3 and 4 without any status change).
    // The friction status counts at closed points only, as stick (1) or slip (2): under a
    // contact fixed point the reported status is the frozen one, the zone the iterate's.
    const int friction = s.zone >= 3 ? (s.status == 2 ? 2 : 1) : 0;
    const Entry e{s.zone, friction, s.gap};
    if (!h.entries.empty() && (h.entries.back().zone >= 3) == (e.zone >= 3) &&
        h.entries.back().status == e.status) {
      h.entries.back() = e;
      continue;
    }
    h.entries.push_back(e);
    if (h.entries.size() > 4) h.entries.pop_front();
    const CyclingKind kind = classify(h, s.length);
    if (kind != CyclingKind::None) events.push_back({i, kind});
  }
  return events;
}

CyclingKind CyclingDetector::classify(const History& h, double length) const {
  if (h.entries.size() < 4) return CyclingKind::None;
  const Entry &a0 = h.entries[0], &b0 = h.entries[1], &a1 = h.entries[2], &b1 = h.entries[3];
  const auto closed = [](const Entry& e) { return e.zone >= 3; };
  const auto same = [&](const Entry& x, const Entry& y) {
    return closed(x) == closed(y) && x.status == y.status;
  };
  if (!same(a0, a1) || !same(b0, b1)) return CyclingKind::None;
  // Same contact status: the friction status alternates (stick <-> slip).
  if (closed(a1) == closed(b1)) return closed(a1) ? CyclingKind::StickSlip : CyclingKind::None;
  const int za = a1.zone, zb = b1.zone;
  const auto pair = [&](int x, int y) { return (za == x && zb == y) || (za == y && zb == x); };
  if (pair(1, 3)) return CyclingKind::SubCycling1;
  if (pair(2, 4)) return CyclingKind::SubCycling2;
  if (pair(2, 3) && std::abs(a1.gap) + std::abs(b1.gap) < grazingTolerance_ * length)
    return CyclingKind::Grazing;
  return CyclingKind::ContactFlipFlop;
}

}  // namespace contactlab
