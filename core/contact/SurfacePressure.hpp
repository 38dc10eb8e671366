#pragma once
// A pressure field from nodal contact forces on a surface of quadratic facets. Node-to-segment
// transmits a force f_i at each slave node; p_i = f_i / w_i with a lumped tributary area w_i is a
// pressure on linear facets (the row sums of the surface mass), but not on quadratic ones: a
// tri6 corner's shape function integrates to zero, so a smooth pressure puts almost no force on
// the corners and most on the mid-edge nodes, and f_i / w_i reads ~0 at corners and ~1.2 p at
// mid-edge nodes.
//
// The field reported is the L2 projection of the traction onto the facets' linear field (the
// vertices' hat functions phi_k): g_k = sum_i phi_k(x_i) f_i (a mid-edge node's force shared
// half and half by its edge's ends), M1 p = g with M1_kl = int phi_k phi_l dA, and a mid-edge
// node's value interpolated from its vertices. When f are the consistent loads of a traction t,
// f_i = int t N_i dA, then g_k = int t phi_k dA exactly (the quadratic basis reproduces the hat
// functions), so a uniform or linear t is given back exactly on any facet type. Projecting onto
// the quadratic field instead (M p = f with the tri6 mass) is exact too, but divides the
// corners' forces, which a smooth pressure makes ~0, by the corners' ~0 integrals: it amplifies
// their errors (the node-to-segment reactions at tri6 corners are short of the consistent load
// by a near-constant amount) into a bias at the vertices (doc/verification.md "Node-to-segment
// on quadratic slave facets").
#include "core/contact/SurfaceWeight.hpp"
#include "core/mesh/Mesh.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace contactlab {

// The field above over the facets of boundary group `group` (reference coordinates): the hat
// functions and M1 built once, so that several force fields on one surface (a pressure and the
// friction's components) share them. M1 p = g is solved by conjugate gradients with a diagonal
// preconditioner to 1e-12 relative, or with M1 lumped (row sums) on line facets. `weight` weighs
// the measure (dA w(x): 2 pi r on an axisymmetric model's rings, whose nodal forces are per ring;
// empty: w = 1).
class SurfaceProjection {
 public:
  SurfaceProjection(const Mesh& mesh, const std::string& group, const SurfaceWeight& weight = {});
  // p for the nodes in `forces` (the others carry no force).
  std::map<std::int64_t, double> field(const std::map<std::int64_t, double>& forces) const;

 private:
  // Each surface node's hat-function values phi_k(x_i) as (vertex, value) pairs (a vertex:
  // itself with 1; a mid-edge node: its two ends with 1/2), and M1 on the vertices.
  std::map<std::int64_t, std::vector<std::pair<int, double>>> hats_;
  std::vector<std::map<int, double>> M1_;
  bool lines_ = true;  // every facet a line: M1 lumped
};

// SurfaceProjection(mesh, group, weight).field(forces): one field.
std::map<std::int64_t, double> pressureFromNodalForces(const Mesh& mesh, const std::string& group,
                                                       const std::map<std::int64_t, double>& forces,
                                                       const SurfaceWeight& weight = {});

}  // namespace contactlab
