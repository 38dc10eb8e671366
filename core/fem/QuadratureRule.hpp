#pragma once
// Quadrature rules on gmsh's reference cells (see ReferenceElement).
//  - lines, quads, hexes: Gauss-Legendre with degree / 2 + 1 points per direction, exact for
//    polynomials of degree `degree` in each direction; first coordinate varies fastest.
//  - triangles: centroid (degree <= 1), 3-point interior rule (2), Radon's 7-point rule (3-5),
//    collapsed Gauss-Legendre (Duffy) above.
//  - tetrahedra: centroid (degree <= 1), 4-point rule (2), collapsed Gauss-Legendre above.
// Simplex rules are exact for polynomials of total degree `degree`. All weights are positive
// and sum to the reference measure (2^d for tensor cells, 1/d! for simplices).
#include "core/mesh/ElementType.hpp"

#include <vector>

namespace contactlab {

struct QuadratureRule {
  int dim = 0;
  std::vector<double> points;  // dim per point
  std::vector<double> weights;

  int size() const { return static_cast<int>(weights.size()); }
};

// Cached: the reference stays valid for the program's lifetime. Throws std::invalid_argument
// for a negative degree.
const QuadratureRule& quadratureRule(ElementType type, int degree);

// Degree integrating the small-strain stiffness B^T C B exactly on undistorted elements:
// 2 * order per direction on tensor cells (2x2(x2) Gauss for quad4/hex8, 3x3(x3) for the
// quadratic ones), 2 * (order - 1) on triangles and tet4 (1 point for tri3/tet4, 3 for tri6),
// and 3 for tet10 (so that curved tet10s pass the patch test).
int stiffnessQuadratureDegree(ElementType type);

}  // namespace contactlab
