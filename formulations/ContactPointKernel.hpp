#pragma once
// The kinematics -> law -> element stage of the contact pipeline: at one paired point, the gap
// g = n . (self x_s - sum_a N_a x_a) and the slip increments v_k = t_k . (the same with the
// displacement increments) along the frozen geometry, their operators B_i on the element's
// displacement dofs, the contact law at (g, v, multipliers), and the element residual B^T r and
// tangent B^T J B (with the law's multiplier rows and columns). Between two pairings g and v are
// linear in u, so the tangent is exact for the frozen geometry; the geometric columns add the
// geometry's derivatives by central differences of the residual with the geometry recomputed.
#include "formulations/ContactControls.hpp"
#include "formulations/ContactDiscretization.hpp"
#include "formulations/ContactPoint.hpp"
#include "formulations/ContactSurfaceState.hpp"
#include "formulations/ContactZone.hpp"

#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace contactlab {

class ContactPointKernel {
 public:
  using Discretizations = std::vector<std::unique_ptr<ContactDiscretization>>;
  // Per zone: its law and friction, and its discretization (the master side, the search
  // distance). All must outlive the kernel.
  ContactPointKernel(int dim, const std::vector<ContactZone>& zones,
                     const Discretizations& discretizations, ContactSurfaceState& state);

  // Multiplies every zone's friction coefficient (ContactControls::setFrictionScale).
  void setFrictionScale(double scale) { frictionScale_ = scale; }
  // The time of the last converged step (an obstacle's translation increment starts there).
  void setConvergedTime(double t) { tConverged_ = t; }
  // Whether the Dirichlet conditions constrain any surface dof (the prescribed-slip check).
  void setSurfaceConstrained(bool constrained) { surfaceConstrained_ = constrained; }

  // The point at time t on the imported state: its result, threshold and indicators, and the
  // element residual `re` (and tangent `ke`, row-major) on its dofs.
  void evaluate(ContactPoint& pt, double t, bool withTangent, std::vector<double>& re,
                std::vector<double>& ke) const;
  // Replaces the displacement columns of `ke` (the frozen-geometry tangent from evaluate) by
  // central differences of the residual with the geometry recomputed (ContactDiscretization::
  // refreshGeometry), the status piece kept, and appends the columns of the point's
  // geometryDofs: ke becomes dofs x (dofs + geometryDofs).
  void geometricColumns(const ContactPoint& pt, double t, GeometricTerms terms,
                        std::vector<double>& ke) const;
  // Normal-field formulations, with the geometry frozen: appends the geometryDofs' columns to
  // `ke` and fills the kinematic rows' displacement columns, -w kappa_n dn(u)/du: in closed form
  // where the discretization has it (ContactDiscretization::currentNormalDerivative), else by
  // central differences of ContactDiscretization::currentNormal.
  void normalFieldColumns(const ContactPoint& pt, double t, std::vector<double>& ke) const;

 private:
  // Widens ke (dofs x dofs) to dofs x (dofs + geometryDofs) and replaces, in every displacement
  // column (the point's, then its geometryDofs'), rows firstRow.. by scale times the central
  // difference of rowsAt, evaluated with that surface position moved by +-h.
  void differenceColumns(const ContactPoint& pt, int firstRow, double scale,
                         const std::function<void(std::vector<double>&)>& rowsAt,
                         std::vector<double>& ke) const;
  // Widens ke and sets rows firstRow..firstRow + dim of every displacement column to scale
  // times the blocks (dn_i/dx_(node, j)). False, ke untouched, when a block's node is not one of
  // the point's columns.
  bool closedFormNormalColumns(const ContactPoint& pt, int firstRow, double scale,
                               const std::map<std::int64_t, std::array<double, 9>>& blocks,
                               std::vector<double>& ke) const;
  // ke (dofs x dofs) widened to dofs x (dofs + geometryDofs), the new columns zero; their count.
  int widenToGeometryColumns(const ContactPoint& pt, std::vector<double>& ke) const;
  // The surface-state position of column j (the point's dofs, then its geometryDofs).
  int columnPosition(const ContactPoint& pt, int column) const;

  int dim_;
  const std::vector<ContactZone>& zones_;
  const Discretizations& discretizations_;
  ContactSurfaceState& state_;
  double frictionScale_ = 1.0, tConverged_ = 0.0;
  bool surfaceConstrained_ = false;
};

}  // namespace contactlab
