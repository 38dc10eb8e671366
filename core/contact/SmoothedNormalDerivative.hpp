#pragma once
// The derivative of the smoothed normal of a faceted surface (Code_Aster's LISSAGE, the
// node-to-segment normal) with respect to the facets' node positions, in closed form:
//   n = n~ / |n~|,  n~ = sum_a N_a nh_a,  nh_a = s_a / |s_a|,  s_a = sum_(f at a) m_f(a),
//   m_f(a) = nu / |nu| the unit normal of facet f at its node a, nu = t x 1 (2D: the tangent
// turned, (t_y, -t_x)) or t1 x t2 (3D), t_j = sum_b dN_b/dxi_j x_b,
// so dn/dx_b = P(n)/|n~| sum_a N_a P(nh_a)/|s_a| sum_(f at a and b) P(m_f(a))/|nu| dnu/dx_b,
// P(v) = I - v v^T. It replaces 2 x (the dofs it depends on) evaluations of the normal by
// central differences, which dominated a 3D normal-field run's contact terms (doc/verification.md
// "The normal-field augmented Lagrangian").
#include "core/contact/ContactSearch.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace contactlab {

// dn_i/dx_(b,j) at [i * 3 + j] for each node b the normal depends on. `facets` (their mesh nodes
// in `facetNodes`, nodesPerFacet each) must include every facet around each of `pointNodes`,
// the nodes interpolated with the values N (as nodalNormals sees them). Empty when the
// interpolated normal vanishes (no derivative: the normal falls back to the facet's).
std::map<std::int64_t, std::array<double, 9>> smoothedNormalDerivative(
    const std::vector<Facet>& facets, const std::vector<std::int64_t>& facetNodes,
    const std::vector<std::int64_t>& pointNodes, const std::vector<double>& N);

}  // namespace contactlab
