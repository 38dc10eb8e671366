#include "formulations/ContactPointResult.hpp"

#include <algorithm>

namespace contactlab {

std::vector<std::string> unknownNames(const std::vector<ContactPointResult>& points) {
  std::vector<std::string> names;
  for (const ContactPointResult& p : points)
    for (const auto& [name, value] : p.unknowns)
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  return names;
}

double unknownValue(const ContactPointResult& point, const std::string& name, double absent) {
  for (const auto& [n, value] : point.unknowns)
    if (n == name) return value;
  return absent;
}

ContactResultants contactResultants(const std::vector<ContactPointResult>& points,
                                    const std::vector<double>& outputPressure) {
  ContactResultants r;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ContactPointResult& p = points[i];
    if (p.status == ContactStatus::Free) continue;
    ++r.contact;
    switch (outputStatus(p)) {
      case 1:
        ++r.stick;
        break;
      case 2:
        ++r.slip;
        break;
      default:
        ++r.closedFrictionless;
    }
    for (int c = 0; c < 3; ++c) {
      r.normalForce[c] += p.weight * p.pressure * p.normal[c];
      r.tangentialForce[c] += p.weight * p.traction[c];
    }
    r.normalForceMagnitude += p.weight * p.pressure;
    r.maxPressure = std::max(r.maxPressure, outputPressure[i]);
    r.maxPenetration = std::max(r.maxPenetration, -p.gap);
  }
  return r;
}

}  // namespace contactlab
