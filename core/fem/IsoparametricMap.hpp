#pragma once
// Isoparametric geometry from nodal coordinates `x` (3 per node, z = 0 in 2D) and reference
// shape derivatives `dNdxi` (ReferenceElement layout: dNdxi[a * refDim + j]). No allocation.
//
// Validity: a cell is degenerate where |det J| <= kDegenerateTolerance * prod_j |dx/dxi_j|
// (Hadamard's bound makes the ratio a scale- and stretch-invariant angle measure in [-1, 1]),
// otherwise inverted where det J < 0. Facets are degenerate likewise where
// |dx/dxi_0 x dx/dxi_1| (3D) or |dx/dxi| (2D) is negligible. Failures throw
// InvalidElementError without the element's identity (see InvalidElementError.hpp).
//
// Facet normals: in 3D n = (dx/dxi_0 x dx/dxi_1) / |..|, i.e. the right-hand rule on gmsh's node
// order (0 -> 1 -> 2 counter-clockwise seen from the side n points to); in 2D, with tangent
// t = dx/dxi (from node 0 towards node 1), n = (t_y, -t_x) / |t|: outward for a boundary
// traversed counter-clockwise around the body.
#include "core/fem/InvalidElementError.hpp"

namespace contactlab {

constexpr double kDegenerateTolerance = 1e-10;

// J[i * dim + j] = dx_i / dxi_j for a dim-cell in dim-space (dim = 1, 2, 3).
void jacobian(int dim, int numNodes, const double* x, const double* dNdxi, double* J);

// Inverse of a dim x dim matrix (row major); returns det. Does not check for singularity.
double invert(int dim, const double* J, double* Jinv);

// Physical gradients dNdx[a * dim + i] = dN_a / dx_i of a dim-cell in dim-space; returns
// det J (> 0). Throws InvalidElementError when inverted or degenerate.
double physicalGradients(int dim, int numNodes, const double* x, const double* dNdxi, double* dNdx);

// Area element dA (length element in 2D) of a (spaceDim - 1)-facet in spaceDim-space
// (spaceDim = 2 or 3) and its unit normal (3 components, z = 0 in 2D). Throws
// InvalidElementError when degenerate.
double facetGeometry(int spaceDim, int numNodes, const double* x, const double* dNdxi,
                     double* normal);

// Physical position x = sum_a N_a x_a (3 components).
void interpolatePosition(int numNodes, const double* x, const double* N, double* point);

}  // namespace contactlab
