#pragma once
// Friction at a contact point whose tangential motion the Dirichlet or symmetry conditions
// already fix (a slave node on a symmetry axis or plane, a supported corner in contact). The slip
// operators B_k of such a direction vanish on every free dof, so its friction multiplier appears in
// no free row: the stick law's row (Lambda - Lambda^ = -r_t v) is zero there and the tangent is
// singular, with every algorithm. code_aster asks the user to list such nodes (SANS_GROUP_NO_FR);
// here they are found from B: the directions q of the tangent plane with B_q = sum_k q_k B_k = 0 on
// the free dofs, or below 0.1 % of the slip operator there (a mortar row that reaches a free node
// by a sliver cannot hold a multiplier either). Their multiplier component q . Lambda is dropped
// (set to 0 by its own row): the force along q is the support's, and the friction law acts on the
// free directions. The other rows are rotated with the same orthonormal basis (an invertible
// recombination of the equations, so the free direction's law is unchanged).
//
// Dropped only while the point does not slide along that direction. A node the supports move
// along a fixed master (a tube's pulled end on its hole, an obstacle driven past a held node)
// has a known, nonzero slip there: Coulomb's force is then mu p along it, a slip row of the law
// (regular: its multiplier is fixed by the slip's direction), not the support's. Dropping it
// there would take the node's friction away under Lagrange (its force is the multiplier) and
// leave only the regularized part c_t v of it under the augmented Lagrangian.
//
// A slave node on a symmetry plane drops the friction along the plane's normal too, whatever B
// says: the tangential traction across a symmetry plane is zero by symmetry. B alone misses it
// where the master point lies a little inside a facet whose other nodes are off the plane (a
// faceted hole's chord): that direction's free part is then small, above the 0.1 % test but too
// small to hold its multiplier, and the tangent turns singular once the point slips.
#include "formulations/ContactLaw.hpp"

#include <array>
#include <vector>

namespace contactlab {

struct PrescribedSlip {
  int prescribed = 0;  // directions of the tangent plane whose slip is prescribed (0..nt)
  // Orthonormal basis of the tangent plane in the point's (t1, t2) coordinates, as columns:
  // the free directions first, the prescribed ones last.
  std::array<std::array<double, 2>, 2> basis{{{1, 0}, {0, 1}}};
  // The prescribed directions are fixed by the supports alone, to round-off: no symmetry plane
  // and no sliver of free motion (a mortar row reaching a free master node by a shape value of
  // 1e-3) prescribes them, so their slip is the supports' motion (prescribedDirectionSlides).
  bool bySupports = false;
};

// B: (1 + nt) x nu row-major operators (row 0 the gap, rows 1..nt the slips) on the element's
// displacement dofs; free[a] whether dof a is free (not Dirichlet); `removed`: orthonormal
// directions over the nu dofs, on free dofs only, that the free space also lacks (the normal of
// an inclined symmetry plane at a node): the motion allowed is the free dofs less these.
// `symmetric`: the normals of the symmetry planes through the slave node in the point's (t1, t2)
// coordinates (n . t1, n . t2); a normal that lies mostly in the tangent plane (|s| > 1/2, the
// contact normal in the symmetry plane) prescribes its direction.
PrescribedSlip prescribedSlip(const std::vector<double>& B, int nt, int nu,
                              const std::vector<char>& free,
                              const std::vector<std::vector<double>>& removed = {},
                              const std::vector<std::array<double, 2>>& symmetric = {});

// Whether the supports fix the gap at the point: the free part of the gap's operator (row 0 of
// B, over the allowed motion as above) is below 0.1 % of the whole, as for a friction direction.
// A slave node held in every direction against a master that is held too (a sheet's clamped edge
// on a fixed die, a node against an obstacle): its normal multiplier would appear in no free row
// and the tangent would be singular. Such a point is opened (no contact unknown acts there): the
// supports carry whatever force the contact would, and the gap is theirs to set.
bool prescribedGap(const std::vector<double>& B, int nu, const std::vector<char>& free,
                   const std::vector<std::vector<double>>& removed = {});

// Whether the point slides along a direction the supports prescribe: `v`, the slip increment in
// (t1, t2); `relativeMotion`, the norm of the whole relative displacement increment (normal
// part included), against which a slip of round-off (1e-8 of it) is none.
bool prescribedDirectionSlides(const PrescribedSlip& slip, int nt, const std::array<double, 2>& v,
                               double relativeMotion);

// Replaces the friction multipliers' rows of `out` (law variables 2 + nt .. 1 + 2 nt, after the
// kinematic ones and p) as described above. Lambda: the multipliers at the point.
void dropPrescribedFriction(const PrescribedSlip& slip, int nt, double weight,
                            const std::array<double, 2>& Lambda, int size, LawOutput& out);

}  // namespace contactlab
