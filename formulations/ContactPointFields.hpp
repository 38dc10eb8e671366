#pragma once
// The contact points' results as fields: the pressure a user reads (recovered from the nodal
// forces where the law's value is not a pressure) and the point data of the VTK output.
#include "core/io/MeshPiece.hpp"
#include "core/mesh/Mesh.hpp"
#include "formulations/ContactPointResult.hpp"
#include "formulations/ContactZone.hpp"

#include <cstdint>
#include <vector>

namespace contactlab {

// The output pressure of each point: on node-to-segment slaves of tri6, quad8 or quad9 facets
// the linear field the points' forces represent (SurfacePressure.hpp), elsewhere NaN (the
// law's pressure is the field). `points` are a converged state's, in the problem's order.
std::vector<double> recoveredPressures(const Mesh& mesh, const std::vector<ContactZone>& zones,
                                       const std::vector<ContactPointResult>& points);

// Adds contact_pressure, tangential_traction, gap, slip, contact_status and cycling on `nodes`
// (a piece's points in the solid's overlap-node order); a node in two zones shows the first.
void addContactPointData(const std::vector<std::int64_t>& nodes,
                         const std::vector<ContactPointResult>& points, MeshPiece& piece);

}  // namespace contactlab
