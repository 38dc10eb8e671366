#pragma once
// A pressure field from nodal contact forces on a surface of quadratic facets. Node-to-segment
// transmits a force f_i at each slave node; p_i = f_i / w_i with a lumped tributary area w_i is a
// pressure on linear facets (the row sums of the surface mass), but not on quadratic ones: a
// tri6 corner's shape function integrates to zero, so a smooth pressure puts almost no force on
// the corners and most on the mid-edge nodes, and f_i / w_i reads ~0 at corners and ~1.2 p at
// mid-edge nodes (a 3D Hertz on tet10: 40 % RMS error against the analytic field). The field
// p = sum_j N_j p_j whose consistent nodal forces are f, M p = f with M_ij = int N_i N_j dA, is
// the pressure those forces represent (the L2 projection of the traction onto the surface's
// field); it is exact for a uniform pressure on any facet type.
#include "core/mesh/Mesh.hpp"

#include <cstdint>
#include <map>
#include <string>

namespace contactlab {

// M p = f over the facets of boundary group `group` (reference coordinates), for the nodes in
// `forces` (the others carry no force); solved by conjugate gradients with a diagonal
// preconditioner to 1e-12 relative. Returns p for the nodes of `forces`.
std::map<std::int64_t, double> pressureFromNodalForces(
    const Mesh& mesh, const std::string& group, const std::map<std::int64_t, double>& forces);

}  // namespace contactlab
