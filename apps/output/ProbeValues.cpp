#include "apps/output/ProbeValues.hpp"

#include <vector>

namespace contactlab {

ProbeValues::ProbeValues(const SceneModel& sm, const Problem& problem)
    : sm_(sm), problem_(problem) {}

void ProbeValues::record(const Vector& u, double t) {
  for (const auto& p : sm_.probes) {
    JsonValue value = JsonValue::array();
    if (p.field == "displacement") {
      const auto d = problem_.nodeDisplacement(u, p.node);
      for (int c = 0; c < problem_.dim(); ++c)
        value.push(d[c]);
    } else {
      for (double s : problem_.nodeStress(u, p.node, t))
        value.push(s);
    }
    const double* x = &sm_.model.mesh->coords[3 * p.node];
    probes_.set(
        p.name,
        JsonValue::object()
            .set("field", p.field)
            .set("point", JsonValue::array(std::vector<double>(p.point.begin(), p.point.end())))
            .set("node", JsonValue::array(std::vector<double>(x, x + 3)))
            .set("distance", p.distance)
            .set("value", value));
  }
}

}  // namespace contactlab
