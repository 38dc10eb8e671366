#pragma once
// The geometric kernel of mortar contact for one slave facet S and its candidate master facets:
//
//   D_jk = int_S Phi_j N_k^S dA,   M_jl^(m) = int_S Phi_j N_l^(m) dA
//
// both over the part of S that the masters' projections cover (so D is the full-facet matrix
// only where S is fully covered). N are the facets' shape functions (ReferenceElement), Phi_j
// the multiplier basis on S. The caller forms weighted gaps n_j . (sum_k D_jk x_k -
// sum_l M_jl x_l) and assembles; nothing here knows a mesh or a map.
//
// Segmentation (where each master covers S) and integration:
//  - 2D (line2, line3; Yang, Laursen & Meng 2005): projection along the slave's continuous normal
//    field n(xi) = normalized sum_j N_j(xi) n_j of the given nodal normals. A master's end nodes
//    are projected onto S, the interval clipped to [-1, 1], Gauss-Legendre in xi over it; at each
//    point the master coordinate is where the line x_S(xi) + s n(xi) meets the master.
//  - 3D (tri3, tri6, quad4, quad8, quad9; Puso & Laursen 2004, Popp, Gee & Wall 2010): an
//    auxiliary plane through the slave's centre x0, normal n0 = the interpolated nodal normal
//    there. Slave and master polygons (quadratic facets split into 4 linear sub-facets through
//    their mid-nodes) are projected on it along n0 and clipped; the (convex) clip polygons are
//    fanned into triangles from a vertex and integrated by a triangle Gauss rule. At each point p
//    the facets' coordinates solve x(xi) = p + alpha n0 (Newton on the full facet map, so curved
//    quadratic facets are integrated on their true surface); the plane's area element becomes
//    the slave's by dA_S = dA_plane / |n_S(xi) . n0|.
// Rules: 2D Gauss-Legendre exact to degree 2 (p_S + p_M) + 2 (p: facet order); 3D the triangle
// rule of total degree max(q_S + q_M, 2 p_S + 2), with q the total degree of a facet's shape
// functions (p for triangles, 2p for quads): exact for D and M between flat facets whose
// projections are affine (triangles, parallelograms).
//
// Multiplier bases: standard (Phi_j = N_j^S) or dual (Phi_j = sum_k A_jk N_k^S, biorthogonal:
// int_C Phi_j N_k dA = delta_jk int_C N_k dA over the covered part C of S, so D is diagonal; on
// a fully covered facet A is the whole facet's, on a partially covered one it is built on C
// where every int_C N_j > 0 (always on linear facets; else the whole facet's A is kept), and
// coverage below 1e-6 of the facet counts as none).
// On tri6 and quad8 facets the corner shape functions integrate to zero and to a negative value,
// so weighted gaps with Phi = N would vanish there and the dual basis would not exist. Both bases
// are then built on the transformed functions T N (multiplierBasisTransform; Lamichhane &
// Wohlmuth 2004, Popp, Gitterle, Gee & Wall 2010, alpha = 1/5 as in Popp's and CalculiX's
// quadratic mortar): standard Phi = T N, dual biorthogonal to T N. T N spans the same space as
// N and sums to 1, so a uniform traction has equal nodal multipliers; only the displacement
// side keeps N (D_jk = int Phi_j N_k is then not diagonal on these facets).
#include "core/contact/ContactSearch.hpp"
#include "core/contact/SurfaceWeight.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace contactlab {

enum class MultiplierBasis { Standard, Dual };

struct MortarMaster {
  std::size_t facet = 0;  // index in the `masters` argument of integrateMortar
  std::vector<double> M;  // row major ns x nm (slave nodes x this master's nodes)
};

// A scalar field over a facet, at a point x (3 components) of it.
using FacetField = std::function<double(const double* x)>;

struct MortarIntegrals {
  std::vector<double> D;              // row major ns x ns
  std::vector<double> field;          // integrateWholeFacet with a field: int Phi_j f dA
  std::vector<MortarMaster> masters;  // the masters that overlap S, in the order given
  double coveredArea = 0.0;           // area of S covered by the masters' projections
  double area = 0.0;                  // area (length in 2D) of S
};

// Mortar integrals of `slave` against `masters` (same dimension as the slave; pass only
// candidates: a master that does not overlap costs its projection and is not listed).
// `slaveNormals`: the unit nodal normals at the slave's nodes (averaged over the facets around
// each node, as nodalNormals gives them); 2D projects along their interpolation, 3D takes the
// auxiliary plane's normal from them. Overlaps among the masters are counted twice: the caller
// passes a non-overlapping master surface. Of the overlapping masters only those of the surface
// nearest to the slave, facing it and within `searchDistance` count (MortarMasterSelection.hpp).
// Throws std::invalid_argument for a facet that is not line2/line3/tri3/tri6/quad4/quad8/quad9,
// masters of another dimension than the slave, wrong coordinate or normal counts, a degenerate
// facet (zero length or area), slave normals tangent to the slave (or cancelling), the dual
// basis on a distorted slave (dualBasisCoefficients), a facet whose projection on the auxiliary
// plane self-intersects. Throws std::runtime_error when an integration point's projection along the
// normal onto a facet does not converge (a facet nearly parallel to the projection direction). In
// 2D a master whose end nodes cannot be projected onto the slave (Newton diverges: far beyond a
// curved slave's ends) counts as not overlapping. Thread-safe: no shared mutable state.
// `weight` (2D only, else std::invalid_argument): every dA, D's, M's, the areas' and the dual
// basis's, becomes dA w(x) at the slave point x (SurfaceWeight.hpp: 2 pi r on an axisymmetric
// model's rings).
MortarIntegrals integrateMortar(const Facet& slave,
                                const std::vector<std::array<double, 3>>& slaveNormals,
                                const std::vector<const Facet*>& masters, MultiplierBasis basis,
                                const SurfaceWeight& weight = {}, double searchDistance = HUGE_VAL);

// D_jk = int_S Phi_j N_k dA over the whole of S (no master: a rigid obstacle covers every facet),
// in the basis `basis` built as integrateMortar builds it on a fully covered facet (the dual
// basis biorthogonal to T N, or T N itself); the row sums are the weights int_S Phi_j dA.
// With `field`, also int_S Phi_j f(x) dA into `field` of the result (an obstacle's gap). Its
// `masters` are empty and its coveredArea the area. Throws as integrateMortar.
MortarIntegrals integrateWholeFacet(const Facet& slave, MultiplierBasis basis,
                                    const SurfaceWeight& weight = {}, const FacetField& field = {});

// Coefficients B (row major ns x ns) of the dual basis on `slave`, Phi = B N: B = A T with
// A = D_e M_e^-1, D_e = diag(int_S T N dA), M_e = int_S T N (T N)^T dA over the whole facet.
// Throws std::invalid_argument when some int_S (T N)_j dA <= 0 (a distorted facet).
std::vector<double> dualBasisCoefficients(const Facet& slave);

// The multiplier basis transform T (row major n x n) of a facet type: the identity, but on tri6
// and quad8, where a corner's function gains alpha = 1/5 of each mid-edge function beside it
// and a mid-edge function keeps 1 - 2 alpha of itself. int T N is then positive on undistorted
// facets: tri6 2A/15 at corners, A/5 at mid-edges; quad8 A/20 and A/5.
std::vector<double> multiplierBasisTransform(ElementType type);
// The facet types whose corner shape functions integrate to zero or below (tri6, quad8): their
// multiplier bases are built on T N, and node-to-segment's collocation there is not sound.
bool hasTransformedBasis(ElementType type);

// The transform a facet's multiplier bases are built on, from its whole-facet integrals
// int N_j w dA: the type's, and on a line3 facet whose corner integrates to 0 under the weight
// (an axisymmetric ring's facet at the axis, w = 2 pi r) the same alpha = 1/5 transform, which
// gives that corner a positive integral; without it the dual basis would not exist there.
std::vector<double> facetBasisTransform(ElementType type, const std::vector<double>& lumped);

}  // namespace contactlab
