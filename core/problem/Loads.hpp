#pragma once
// Boundary conditions and loads of a solid model. Values scale with a load function of time;
// the optional `field` callbacks (used by manufactured-solution tests and future scene
// expressions) replace the constant value when set.
#include "base/PiecewiseLinear.hpp"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace contactlab {

// Scale factor of a load at time t: `ramp` is 0 until startTime, then grows linearly to 1 at
// t = endTime and holds 1 after it (sequenced loading: press first, then shift); `constant` is
// 1 at every time; `table` interpolates (times[i], factors[i]) linearly and holds the first and
// last factors outside them (a load that rises and falls: an expansion pressure, then its
// release).
struct LoadFunction {
  enum class Kind { Ramp, Constant, Table };
  Kind kind = Kind::Ramp;
  double endTime = 1.0;
  double startTime = 0.0;
  std::vector<double> times, factors;  // table: strictly increasing times, same sizes
  // The times where the function has a kink (a ramp's start and stop, a table's times): a load
  // step that passes one cuts the corner of the history, e.g. the peak of a load table.
  std::vector<double> kinks() const {
    if (kind == Kind::Constant) return {};
    if (kind == Kind::Table) return times;
    return {startTime, endTime};
  }
  double operator()(double t) const {
    if (kind == Kind::Constant) return 1.0;
    if (kind == Kind::Table) return piecewiseLinear(times, factors, t);
    if (t <= startTime) return 0.0;
    return t >= endTime ? 1.0 : (t - startTime) / (endTime - startTime);
  }
};

struct DirichletCondition {
  std::string name;             // the scene's key, for messages and reactions
  std::string group;            // boundary physical group
  std::vector<int> components;  // 0 = x, 1 = y, 2 = z
  double value = 0.0;
  LoadFunction function;
  std::function<double(const double* x, int component, double t)> field;  // optional
};

struct SurfaceLoad {
  enum class Kind { Pressure, Traction };
  // A pressure either follows the deformation (on the current facet, with its load stiffness
  // in the tangent: a follower load) or acts on the reference facet (a dead load). Automatic:
  // follower where the facet's element is finite-strain, dead where it is small-strain.
  // Tractions are dead loads.
  enum class Follower { Automatic, Yes, No };
  std::string name;
  std::string group;
  Kind kind = Kind::Pressure;
  double pressure = 0.0;  // acts against the outward normal
  Follower follower = Follower::Automatic;
  std::array<double, 3> traction{{0, 0, 0}};  // force per unit area
  LoadFunction function;
  std::function<void(const double* x, double t, double* traction)> field;  // optional
};

struct BodyForce {
  std::string name;
  std::string block;                       // empty: every block
  std::array<double, 3> value{{0, 0, 0}};  // force per unit volume
  LoadFunction function;
  // optional; writes one component per spatial dimension
  std::function<void(const double* x, double t, double* force)> field;
};

// The centrifugal force of a body spinning at angular velocity omega about an axis (2D: the
// z axis through `centre`): rho omega^2 r per unit reference volume, r the position's distance
// vector from the axis. A follower load takes r at the current position x = X + u (mass is
// conserved, so rho dV0 of the reference volume is the spinning mass); its load stiffness
// -df/du = -rho omega^2 M P (M the consistent mass matrix of unit density, P the projector
// normal to the axis) is symmetric and softening. A dead load takes r at the reference position.
// Automatic: follower on finite-strain blocks, dead on small-strain ones. The load function
// scales the force (omega^2).
struct CentrifugalLoad {
  std::string name;
  std::string block;  // empty: every block
  double density = 0.0;
  double angularVelocity = 0.0;             // rad per unit time
  std::array<double, 3> centre{{0, 0, 0}};  // a point of the axis
  std::array<double, 3> axis{{0, 0, 1}};    // unit direction (2D: z)
  SurfaceLoad::Follower follower = SurfaceLoad::Follower::Automatic;
  LoadFunction function;
};

// A symmetry (roller) condition on a plane group: every node keeps n . u = 0 and slides freely
// in the plane. `normal` zero: the plane fitted through the group's nodes. A plane normal to an
// axis is the Dirichlet condition u_axis = 0; an inclined one is eliminated exactly, one
// dependent component per node (LinearConstraints.hpp).
struct SymmetryCondition {
  std::string name;
  std::string group;
  std::array<double, 3> normal{{0, 0, 0}};
};

// A tie between the dofs of nodes (code_aster's LIAISON_DDL, Abaqus' *EQUATION): for each listed
// component c and each matched tuple of nodes, one from each group,
//   sum_i coefficients[i] u_c(node_i) = 0,
// imposed exactly by eliminating one dof per equation (LinearConstraints.hpp). Groups of one
// node tie those nodes; groups of several nodes (the same count in each) are matched by the
// translation between the groups' centroids (coincident interfaces, periodic faces).
struct TieCondition {
  std::string name;
  std::vector<std::string> groups;   // boundary physical groups or point groups
  std::vector<double> coefficients;  // one per group, not all zero
  std::vector<int> components;       // 0 = x, 1 = y, 2 = z
  // The right side of each equation, value * function(t) (code_aster's COEF_IMPO): 0 ties the
  // nodes; otherwise it prescribes their relative motion, e.g. u_a - u_b = an opening.
  double value = 0.0;
  LoadFunction function;
};

// A discrete spring from each node of a group to ground: in every listed component, a force
// -stiffness * u on the node (residual +k u, tangent +k on the diagonal). The stiffness is per
// node and per component, so the group's total stiffness in a component is k times its nodes.
struct NodalSpring {
  std::string name;
  std::string group;            // boundary physical group (any dimension: points too)
  std::vector<int> components;  // 0 = x, 1 = y, 2 = z
  double stiffness = 0.0;       // force per unit length, > 0
};

// A force on the nodes of a group: `force` is either the group's total, shared equally by its
// nodes (Total), or what each node gets (PerNode). A dead load.
struct PointLoad {
  enum class Distribution { Total, PerNode };
  std::string name;
  std::string group;
  std::array<double, 3> force{{0, 0, 0}};
  Distribution distribution = Distribution::Total;
  LoadFunction function;
};

// The prescribed temperature of an element block, uniform over it (a thermal load: no heat
// conduction is solved): T(t) = T_ref + (value - T_ref) f(t), T_ref the block material's
// stress-free temperature (Material::referenceTemperature, the one place it is given), so that
// f = 0 leaves the block stress-free and f = 1 puts it at `value`.
struct BlockTemperature {
  std::string block;   // element block (the scene's key)
  double value = 0.0;  // degC, at f = 1
  LoadFunction function;
  double at(double referenceTemperature, double t) const {
    return referenceTemperature + (value - referenceTemperature) * function(t);
  }
};

}  // namespace contactlab
