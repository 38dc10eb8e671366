#pragma once
// Local frames of contact surfaces: a deterministic tangent basis for a normal, and the nodal
// normals of a faceted master surface (averaged over the facets around each node), which give
// a normal field continuous across the kinks between facets when interpolated.
#include "core/contact/ContactSearch.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace contactlab {

// t1, t2 completing the unit normal n to an orthonormal frame. 2D (dim = 2): t1 = (-n_y, n_x),
// t2 = 0. 3D: the coordinate axis least aligned with n made orthogonal to it, then t2 = n x t1.
// Deterministic: every rank and every update picks the same basis for the same normal.
void tangentBasis(int dim, const std::array<double, 3>& n, std::array<double, 3>& t1,
                  std::array<double, 3>& t2);

// The frame of a point that already has one (t1 in, the new t1 out): as tangentBasis, but 3D
// keeps the axis the old t1 was built from while it stays far enough from n. A normal on a tie
// (|n_x| = |n_y| on a symmetric mesh's diagonal) would otherwise let round-off turn t1 by 90
// degrees between two updates, and with it the tangential multipliers and the friction history
// held in that frame, which would then be read in the other frame. t1 = 0 (a first frame):
// tangentBasis's.
void tangentBasisFollowing(int dim, const std::array<double, 3>& n, std::array<double, 3>& t1,
                           std::array<double, 3>& t2);

// Unit normal at each node of `facets` (facetNodes: the mesh nodes of facet f at
// [f * nodesPerFacet, (f + 1) * nodesPerFacet)): the normalized sum of the normals of the
// facets around the node, each evaluated at that node.
std::map<std::int64_t, std::array<double, 3>> nodalNormals(
    const std::vector<Facet>& facets, const std::vector<std::int64_t>& facetNodes);

}  // namespace contactlab
