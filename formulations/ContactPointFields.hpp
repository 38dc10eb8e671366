#pragma once
// The contact points' results as fields: the pressure and traction a user reads (recovered from
// the nodal forces where the law's values are not a pressure and a traction) and the point data of
// the VTK output.
#include "core/io/MeshPiece.hpp"
#include "core/mesh/Mesh.hpp"
#include "formulations/ContactPointResult.hpp"
#include "formulations/ContactZone.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace contactlab {

// The output pressure and tangential traction of each point: on node-to-segment slaves of tri6,
// quad8 or quad9 facets and on axisymmetric rings, the linear fields the points' forces
// represent (SurfacePressure.hpp; the traction on frictional zones only), elsewhere NaN (the
// law's values are the fields). `points` are a converged state's, in the problem's order.
struct RecoveredFields {
  std::vector<double> pressure;
  std::vector<std::array<double, 3>> traction;
};
RecoveredFields recoveredFields(const Mesh& mesh, const std::vector<ContactZone>& zones,
                                const std::vector<ContactPointResult>& points);

// Adds contact_pressure, tangential_traction, gap, slip, contact_status and cycling on `nodes`
// (a piece's points in the solid's overlap-node order); a node in two zones shows the first.
void addContactPointData(const std::vector<std::int64_t>& nodes,
                         const std::vector<ContactPointResult>& points, MeshPiece& piece);

}  // namespace contactlab
