#include "formulations/ContactPointFields.hpp"

#include "core/contact/SurfacePressure.hpp"
#include "formulations/ContactDiscretizationType.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace contactlab {

RecoveredFields recoveredFields(const Mesh& mesh, const std::vector<ContactZone>& zones,
                                const std::vector<ContactPointResult>& points) {
  const double nan = std::nan("");
  RecoveredFields recovered;
  recovered.pressure.assign(points.size(), nan);
  recovered.traction.assign(points.size(), {nan, nan, nan});
  for (std::size_t z = 0; z < zones.size(); ++z) {
    if (!contactDiscretizationType(zones[z].discretization).traits().collocatesAtSlaveNodes)
      continue;
    // Quadratic 3D facets: on tri6 f / w is not a pressure (corner integrals 0), on quad8 the
    // corner integrals are negative, and on quad9 f / w is a lumped projection with a small
    // corner share; the linear field of SurfacePressure.hpp is the traction there (3D Hertz,
    // hertz-3d's sizes, RMS off Hertz: tet10 40 % -> 1.9 %, hex20 46 % -> 3.8 %, hex27 6.1 % ->
    // 1.8 %). Plane line2 and line3 facets keep f / w, a lumped projection there (hertz-2d
    // quad8: 1.04 % against 1.07 %). Axisymmetric rings do not: their lumped (HRZ) areas with
    // the weight 2 pi r are not the row sums of the weighted mass, and at the axis f / w read
    // 4/3 p (line2) and 0 (line3, whose corner there integrates r to 0). doc/verification.md.
    bool projected = static_cast<bool>(zones[z].areaWeight);
    for (const CellGroup* g : mesh.findBoundaries(zones[z].slave))
      projected |= g->type == ElementType::Tri6 || g->type == ElementType::Quad8 ||
                   g->type == ElementType::Quad9;
    if (!projected) continue;
    auto inZone = [&](const ContactPointResult& p) { return p.zone == static_cast<int>(z); };
    // The field of the nodal forces w_i v_i (an open point's are 0), at the zone's points.
    const SurfaceProjection projection(mesh, zones[z].slave, zones[z].areaWeight);
    auto field = [&](auto value) {
      std::map<std::int64_t, double> forces;
      for (const ContactPointResult& p : points)
        if (inZone(p)) forces[p.node] = p.status == ContactStatus::Free ? 0.0 : p.weight * value(p);
      return projection.field(forces);
    };
    const auto pressure = field([](const ContactPointResult& p) { return p.pressure; });
    for (std::size_t i = 0; i < points.size(); ++i)
      if (inZone(points[i]))
        // A field value, also at a node whose own force is ~0 (a tri6 corner, often open in
        // the law for that reason); the projection's undershoot at the zone's edge is cut at 0.
        recovered.pressure[i] = std::max(0.0, pressure.at(points[i].node));
    // The friction force's field too, so that a slipping point's traction is mu times the
    // pressure beside it (the law's own f / w is not a traction wherever its pressure is not:
    // at 0.45 to 1.05 mu p on a fully slipping quad8 ring, tube-pull-out-axisymmetric).
    if (zones[z].friction == 0) continue;
    // Where the pressure's undershoot was cut at 0, so is the traction: no friction without it.
    for (int c = 0; c < 3; ++c) {
      const auto traction = field([c](const ContactPointResult& p) { return p.traction[c]; });
      for (std::size_t i = 0; i < points.size(); ++i)
        if (inZone(points[i]))
          recovered.traction[i][c] = recovered.pressure[i] > 0 ? traction.at(points[i].node) : 0.0;
    }
  }
  return recovered;
}

void addContactPointData(const std::vector<std::int64_t>& nodes,
                         const std::vector<ContactPointResult>& points, MeshPiece& piece) {
  std::map<std::int64_t, const ContactPointResult*> byNode;
  for (const ContactPointResult& p : points)
    byNode.emplace(p.node, &p);  // first zone wins for a node in two zones
  FieldData pressure{"contact_pressure", 1, {}}, traction{"tangential_traction", 3, {}},
      gap{"gap", 1, {}}, slip{"slip", 3, {}}, status{"contact_status", 1, {}},
      cycling{"cycling", 1, {}};
  for (std::int64_t node : nodes) {
    auto it = byNode.find(node);
    const ContactPointResult* p = it == byNode.end() ? nullptr : it->second;
    pressure.values.push_back(p ? p->pressure : 0.0);
    gap.values.push_back(p && p->paired ? p->gap : 0.0);
    status.values.push_back(p ? static_cast<double>(outputStatus(*p)) : 0.0);
    cycling.values.push_back(p ? static_cast<double>(p->cycling) : 0.0);
    for (int c = 0; c < 3; ++c) {
      traction.values.push_back(p ? p->traction[c] : 0.0);
      slip.values.push_back(p ? p->slip[c] : 0.0);
    }
  }
  for (auto* f : {&pressure, &traction, &gap, &slip, &status, &cycling})
    piece.pointData.push_back(std::move(*f));
  // The formulation's unknowns, one field each (0 where a node has none).
  for (const std::string& name : unknownNames(points)) {
    FieldData field{"unknown_" + name, 1, {}};
    for (std::int64_t node : nodes) {
      auto it = byNode.find(node);
      field.values.push_back(it == byNode.end() ? 0.0 : unknownValue(*it->second, name, 0.0));
    }
    piece.pointData.push_back(std::move(field));
  }
}

}  // namespace contactlab
