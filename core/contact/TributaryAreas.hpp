#pragma once
// Tributary areas of the nodes of a contact surface by HRZ lumping: w_a = A * m_aa / sum_b m_bb
// over each facet, m_aa = int N_a^2 dA. Positive on every facet type (the row sum int N_a dA
// vanishes at tri6 corners and is negative at quad8 corners) and the usual halves on linear
// segments; the sum over the nodes is the surface's area (length in 2D).
#include "core/contact/SurfaceWeight.hpp"
#include "core/mesh/Mesh.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>

namespace contactlab {

using NodePosition = std::function<std::array<double, 3>(std::int64_t node)>;

// The mesh's reference coordinates as a NodePosition (`mesh` must outlive it).
NodePosition referencePositions(const Mesh& mesh);

// Over the facets of boundary group `group` (dim: the mesh's space dimension), with the nodes
// at `position` (the reference coordinates, or a current configuration); dA weighted by
// `weight` at each quadrature point's position when it is given (SurfaceWeight.hpp).
std::map<std::int64_t, double> tributaryAreas(const Mesh& mesh, const std::string& group, int dim,
                                              const NodePosition& position,
                                              const SurfaceWeight& weight = {});

}  // namespace contactlab
