#pragma once
// What a contact point reports after an evaluation, and the sums over a contact surface, as the
// outputs (contact.csv, VTK, steps.csv, summary.json) read them.
#include "formulations/ContactLaw.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace contactlab {

// One contact point at the last evaluation (every rank holds all of them).
struct ContactPointResult {
  int zone = 0;
  std::int64_t node = -1;            // slave mesh node
  std::array<double, 3> x{};         // current position
  double weight = 0;                 // tributary area
  bool paired = false;               // a master point was found within the search distance
  double gap = 0;                    // > 0 apart
  double pressure = 0;               // >= 0
  std::array<double, 3> traction{};  // tangential traction on the slave
  std::array<double, 3> normal{};
  std::array<double, 3> slip{};  // accumulated slip (sum of converged increments)
  ContactStatus status = ContactStatus::Free;
  // The point carries friction: mu > 0 and, if closed, a threshold above round-off
  // (LawOutput::frictionlessClosed); otherwise a closed point is written as closed without
  // friction, not as stick or slip.
  bool frictional = false;
  int cycling = 0;  // cycling kind detected in the step (CyclingKind), 0 none
  // The formulation's unknowns at the point, by name (ContactLaw::pointUnknownNames).
  std::vector<std::pair<std::string, double>> unknowns;
};

// The unknowns' names over a set of points, each once, in the order they first appear.
std::vector<std::string> unknownNames(const std::vector<ContactPointResult>& points);
// The point's unknown of that name, or `absent` when its formulation has none.
double unknownValue(const ContactPointResult& point, const std::string& name, double absent);

// contact_status as written to contact.csv and the VTK output, one meaning everywhere: 0 free,
// 1 stick, 2 slip (frictional points), 3 closed without friction (no stick or slip to tell).
constexpr int kOutputClosedFrictionless = 3;
inline int outputStatus(const ContactPointResult& p) {
  if (p.status == ContactStatus::Free) return 0;
  return p.frictional ? static_cast<int>(p.status) : kOutputClosedFrictionless;
}

struct ContactResultants {
  std::array<double, 3> normalForce{};      // sum w p n (force on the slave surfaces)
  std::array<double, 3> tangentialForce{};  // sum w t
  double normalForceMagnitude = 0;          // sum w p
  double maxPressure = 0;
  double maxPenetration = 0;  // max(-gap) over closed points, >= 0
  int contact = 0, stick = 0, slip = 0, closedFrictionless = 0;
};

// The sums over `points`: forces from the law's pressures (`points`), the largest pressure from
// the output field `outputPressure` (the same points' pressures as written, SurfacePressure.hpp).
ContactResultants contactResultants(const std::vector<ContactPointResult>& points,
                                    const std::vector<double>& outputPressure);

}  // namespace contactlab
