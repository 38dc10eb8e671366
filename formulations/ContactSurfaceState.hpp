#pragma once
// The replicated state every contact stage reads: the displacements of every contact-surface
// node (current and at the last converged step) and every contact multiplier, on every rank.
// Contact surfaces are small, so each rank imports them whole at each evaluation and evaluates
// every point with the same numbers (pairings and statuses agree everywhere).
//
// Layout of the replicated vector: the surface nodes' displacement dofs (node index k, component
// c at k * dim + c), then all multipliers in GID order.
#include "base/LinearAlgebra.hpp"
#include "core/mesh/Mesh.hpp"
#include "core/problem/DofMap.hpp"

#include <array>
#include <cstdint>
#include <set>
#include <vector>

namespace contactlab {

class ContactSurfaceState {
 public:
  // `map`: the monolithic map (the solid's `ownedDisplacements` owned dofs, then the owned
  // multipliers); `constrained`: the solid's Dirichlet flags of its dofs (the owned ones first);
  // `nodes`: the surface nodes.
  ContactSurfaceState(const Mesh& mesh, const DofMap& dofs, Teuchos::RCP<const Map> map,
                      LO ownedDisplacements, const std::set<std::int64_t>& nodes, GO numMultipliers,
                      const std::vector<char>& constrained);

  void import(const Vector& x);
  // The current displacements become the converged ones.
  void commit();

  std::array<double, 3> displacement(std::int64_t node, bool converged) const;
  // Reference coordinates plus the current displacement.
  std::array<double, 3> position(std::int64_t node) const;
  // Positions in the replicated vector: a node's component, a multiplier (by GID).
  int dofPosition(std::int64_t node, int component) const {
    return index_[node] * dim_ + component;
  }
  int multiplierPosition(GO multiplier) const {
    return static_cast<int>(displacementDofs_ + (multiplier - firstMultiplier_));
  }
  std::size_t displacementDofs() const { return displacementDofs_; }
  // Whether a position is a Dirichlet-constrained displacement dof.
  bool constrained(int position) const {
    return static_cast<std::size_t>(position) < displacementDofs_ && constrained_[position];
  }
  Teuchos::ArrayRCP<const double> values() const { return replicated_->getData(0); }
  // For perturbations (finite-difference geometric columns): restore what you change.
  Teuchos::ArrayRCP<double> mutableValues() { return replicated_->getDataNonConst(0); }

 private:
  const Mesh& mesh_;
  int dim_;
  std::vector<int> index_;  // mesh node -> surface node index (-1)
  std::size_t displacementDofs_ = 0;
  GO firstMultiplier_ = 0;
  Teuchos::RCP<Import> importer_;
  Teuchos::RCP<Vector> replicated_;
  std::vector<double> converged_;  // surface dofs at the last converged step
  std::vector<char> constrained_;
};

}  // namespace contactlab
