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

    const Entry e{s.zone, s.status, s.gap};
    if (!h.entries.empty() && h.entries.back().zone == e.zone &&
        h.entries.back().status == e.status) {
      h.entries.back().gap = e.gap;
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
  const bool alternates =
      a0.zone == a1.zone && b0.zone == b1.zone && a0.status == a1.status && b0.status == b1.status;
  if (!alternates) return CyclingKind::None;
  const int za = a0.zone, zb = b0.zone;
  if (za == zb) {
    // Same zone, the friction status alternates.
    return (a0.status != 0 && b0.status != 0) ? CyclingKind::StickSlip : CyclingKind::None;
  }
  const auto pair = [&](int x, int y) { return (za == x && zb == y) || (za == y && zb == x); };
  if (pair(1, 3)) return CyclingKind::SubCycling1;
  if (pair(2, 4)) return CyclingKind::SubCycling2;
  if (pair(2, 3) && std::abs(a1.gap) + std::abs(b1.gap) < grazingTolerance_ * length)
    return CyclingKind::Grazing;
  return CyclingKind::ContactFlipFlop;
}

}  // namespace contactlab
