#pragma once
// The equations of a model's ties (TieCondition, Loads.hpp) and their elimination.
//
// tieEquations() reads each tie's groups and matches their nodes into tuples; every tuple and
// listed component gives one equation sum_i a_i u(node_i, c) = g(t), g the tie's right side
// (TieCondition::value and function; 0: homogeneous). eliminateTies()
// brings the equations to reduced row echelon form by Gauss-Jordan elimination: each equation
// makes one dof dependent (its largest coefficient among the dofs that no Dirichlet condition
// fixes and no earlier equation made dependent; the first such on a tie) and every dependent is
// written in independent dofs only, so a chain of ties (a = b, b = c) or a node tied to several
// resolves. An equation that leaves no free dof (every dof prescribed, or the equation implied
// by earlier ones) makes nothing dependent: the Dirichlet conditions decide those dofs.
#include "core/problem/SolidModel.hpp"

#include <cstdint>
#include <set>
#include <utility>
#include <vector>

namespace contactlab {

// One dof of the mesh: (node, component).
using MeshDof = std::pair<std::int64_t, int>;

struct TieEquation {
  int tie = 0;  // index in model.ties; -1 for a symmetry plane's equation
  // Index in model.symmetries of an inclined plane's n . u = 0 at a tied node (LinearConstraints
  // eliminates it with the ties'), else -1.
  int plane = -1;
  std::vector<MeshDof> dofs;
  std::vector<double> coefficients;  // sum_i coefficients[i] u(dofs[i]) = the tie's right side
};

// u(dof) = sum_j coefficient_j u(term_j) + sum_e w_de g_e, the terms independent dofs.
// `equations`: the reduced row of this dependent as a combination of the original equations
// (by index, w_de), which gives both its right side (sum_e w_de g_e, g_e equation e's) and the
// equations' multipliers: with the residual R balancing the ties' forces (R = A^T mu on the
// tied dofs), mu_e = sum over dependents d of w_de R(d).
struct TiedDof {
  MeshDof dof;
  std::vector<std::pair<MeshDof, double>> terms;
  std::vector<std::pair<int, double>> equations;
};

// Every equation of model.ties. Throws InputError with a sentence for a group that is not one,
// groups of different node counts, a node without a partner at the groups' translation, a node
// tied to itself, or coefficients that do not match the groups.
std::vector<TieEquation> tieEquations(const SolidModel& model);

// Nodes linked by the equations, one sorted list per connected set: the nodes whose dofs one
// rank must own together (DofMap).
std::vector<std::vector<std::int64_t>> linkedNodes(const std::vector<TieEquation>& equations);

// An equation that made no dof dependent (every dof prescribed, or implied by earlier
// equations), and the equations (by index, with weights; itself with 1) whose combination its
// reduced row is: with right sides, that combination of them must vanish.
struct RedundantEquation {
  int equation = 0;
  std::vector<std::pair<int, double>> combination;
};

// The dependents of the equations; `fixed`: the dofs Dirichlet conditions prescribe.
// `redundant`, when given, receives the equations that made nothing dependent.
std::vector<TiedDof> eliminateTies(const std::vector<TieEquation>& equations,
                                   const std::set<MeshDof>& fixed,
                                   std::vector<RedundantEquation>* redundant = nullptr);

}  // namespace contactlab
