#pragma once
// Closest-point projection of a slave point onto a master facet: the first stage of contact
// kinematics (the search that picks candidate facets, and the treatment of kinks between them,
// are not done here).
//
// Facets are line2/line3 in 2D (spaceDim = 2, z = 0) and tri3/tri6/quad4/quad8/quad9 in 3D, with
// nodal coordinates 3 per node in gmsh's node order, on ReferenceElement's reference domains
// (lines and quads on [-1,1]^d, triangles on the unit simplex).
//
// Algorithm: Newton on the stationarity condition g_j = (x(xi) - x_s) . dx/dxi_j = 0 with the full
// Hessian H_jk = dx/dxi_j . dx/dxi_k + (x(xi) - x_s) . d2x/dxi_j dxi_k (curvature term included),
// started at the facet centre. The step falls back to the Gauss-Newton metric where H is not
// positive definite, is limited in length and is damped by an Armijo backtracking line search on
// f = |x(xi) - x_s|^2 / 2, so it descends from any start. When the unconstrained minimum lies
// outside the reference facet (or the iterates leave it by a wide margin), the answer is the
// closest point of the facet's boundary: a clamped 1D Newton on every edge, plus the vertices
// (the two end points in 2D); then inside = false. Safeguard against local minima of curved
// facets: the facet is sampled on a lattice of spacing 1/4 of the reference domain (which holds
// the nodes); Newton restarts from the closest sample when that beats its answer, and the boundary
// is searched when a boundary sample does. Strongly wavy facets can still hide a closer local
// minimum between samples.
//
// Normal convention is IsoparametricMap's facetGeometry: 2D n = (t_y, -t_x)/|t| with t = dx/dxi,
// 3D n = dx/dxi_0 x dx/dxi_1 normalized. gap = (x_s - point) . normal (> 0: separated, < 0:
// penetrating). No allocation.
#include "core/mesh/ElementType.hpp"

namespace contactlab {

// A converged local coordinate counts as inside the reference facet within this tolerance.
constexpr double kProjectionInsideTolerance = 1e-10;

struct Projection {
  double xi[2] = {0.0, 0.0};           // local coordinates of the closest point (xi[1] = 0 in 2D)
  double point[3] = {0.0, 0.0, 0.0};   // closest point on the facet
  double normal[3] = {0.0, 0.0, 0.0};  // unit facet normal at the closest point
  double gap = 0.0;                    // (x_slave - point) . normal
  double distance = 0.0;               // |x_slave - point|
  bool inside = false;                 // unconstrained minimum within the reference facet
  int iterations = 0;                  // Newton iterations, all stages together
  bool converged = false;              // the returned point is a converged stationary point
};

// Closest point on the master facet `facetType` (nodal coordinates `facetCoords`, 3 per node) to
// `slavePoint` (3 components). `tolerance` bounds the last Newton step in reference coordinates.
// Throws std::invalid_argument when facetType is not a facet type of spaceDim.
Projection projectOnFacet(ElementType facetType, int spaceDim, const double* facetCoords,
                          const double* slavePoint, double tolerance = 1e-12,
                          int maxIterations = 30);

// Stationary point of |x(xi) - x_s|^2 / 2 on the facet's polynomial extension, by Newton (full
// Hessian, no clamping) from xiStart: the smooth branch of the projection through a point found
// by projectOnFacet, for derivatives of the pairing where that point sits on the facet's
// boundary (a vertex or edge shared with a neighbour). `inside` tells whether it stays in the
// reference facet; converged = false when Newton does not converge (far from xiStart).
Projection projectOnFacetExtension(ElementType facetType, int spaceDim, const double* facetCoords,
                                   const double* slavePoint, const double* xiStart,
                                   int maxIterations = 20);

// Whether reference coordinates xi lie in the reference domain of facetType (within tolerance).
bool insideReferenceFacet(ElementType facetType, const double* xi,
                          double tolerance = kProjectionInsideTolerance);

}  // namespace contactlab
