#pragma once
// The terms of a solid model that act on single nodes, without an element: springs to ground
// (NodalSpring) and point loads (PointLoad).
//
// Each node's term is assembled by the rank that owns the node (DofMap), so a node on a
// partition boundary contributes once. Owned nodes come first in the overlap numbering, so an
// owned node's overlap dof LID is also its owned row: residual entries go into the overlap
// vector that is exported (ADD) to the owners, tangent entries straight onto the owned
// diagonal.
#include "core/problem/DofMap.hpp"
#include "core/problem/SolidModel.hpp"

#include <array>
#include <vector>

namespace contactlab {

class MatrixAssembler;

class NodalAssembler {
 public:
  // The model's groups must exist (Problem::checkModel checks them).
  NodalAssembler(const SolidModel& model, const DofMap& dofs);

  // r (overlap dofs) += k u at the springs' owned dofs, for the overlap displacement u.
  void addSpringForces(const double* u, std::vector<double>& r) const;
  // k on the owned diagonal of every spring dof that no Dirichlet condition eliminates (a
  // constrained dof keeps its unit diagonal; its spring force goes to the reaction).
  void addSpringStiffness(MatrixAssembler& assembler, const std::vector<char>& constrained) const;
  // Per spring, the force it exerts on the body, -sum k u over this rank's owned nodes (sum
  // over ranks for the total).
  std::vector<std::array<double, 3>> localSpringForces(const double* u) const;
  // f (overlap dofs) += the point loads at time t on their owned nodes.
  void addPointLoads(double t, std::vector<double>& f) const;

 private:
  struct Entry {
    int term;  // index in springs_ or pointLoads_
    int lid;   // owned (and overlap) dof LID
    int component;
    double value;  // spring: k; point load: the node's force at full load
  };

  std::vector<Entry> springEntries_, loadEntries_;
  std::vector<PointLoad> pointLoads_;
  std::size_t numSprings_ = 0;
};

}  // namespace contactlab
