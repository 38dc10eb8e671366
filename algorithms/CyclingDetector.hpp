#pragma once
// Cycling detection per contact point over successive evaluations (doc/algorithms.md "Cycling").
//
// Each point's history keeps its last states with consecutive repeats merged (an iterate that
// keeps its zone is not a flip). A point cycles when its last four distinct states alternate
// a, b, a, b. The kinds, after the seed's decomposition of the normal law into zones
// (ContactPointState::zone) and Code_Aster's friction cycles:
//   sub-cycling-1      zones 1 -> 3 -> 1 -> 3 (apart and open <-> penetrating and closed)
//   sub-cycling-2      zones 2 -> 4 -> 2 -> 4 (the two mixed zones)
//   grazing            zones 2 -> 3 -> 2 -> 3 with |g^N| + |g^N+1| < tol * point length
//   contact-flip-flop  any other open <-> closed alternation
//   stick-slip         a closed point alternating stick and slip
//   slip-reversal      a slipping point whose friction direction reverses twice in a row
#include "formulations/ContactControls.hpp"

#include <array>
#include <deque>
#include <string>
#include <vector>

namespace contactlab {

enum class CyclingKind {
  None = 0,
  SubCycling1,
  SubCycling2,
  Grazing,
  ContactFlipFlop,
  StickSlip,
  SlipReversal,
};
constexpr int kCyclingKinds = 7;  // including None
const char* cyclingKindName(CyclingKind kind);

struct CyclingEvent {
  std::size_t point;
  CyclingKind kind;
};

class CyclingDetector {
 public:
  explicit CyclingDetector(double grazingTolerance = 1e-6) : grazingTolerance_(grazingTolerance) {}
  // Forgets every history (a new load step).
  void reset();
  // Feeds the states of one evaluation; returns the points that started cycling with it (a
  // point is reported again only after its history changed by a new state).
  std::vector<CyclingEvent> observe(const std::vector<ContactPointState>& states);
  // Forgets one point's history: a treatment forced its status, and the change the forcing
  // makes is not a cycle of the point's own.
  void forget(std::size_t point);

 private:
  struct Entry {
    int zone;
    int status;
    double gap;
  };
  struct History {
    std::deque<Entry> entries;  // last distinct (zone, status) pairs, newest last
    std::array<double, 3> lastSlipDirection{};
    bool slipping = false;
    int reversals = 0;
  };
  CyclingKind classify(const History& h, double length) const;

  double grazingTolerance_;
  std::vector<History> histories_;
};

}  // namespace contactlab
