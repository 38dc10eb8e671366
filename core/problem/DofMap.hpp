#pragma once
// Degrees of freedom on Tpetra: `dim` displacement components per mesh node used by an element.
// Each node is owned by the lowest rank among the ranks of its elements; nodes are renumbered
// so that every rank owns a contiguous range (global dof = node * dim + component). The owned
// map holds those dofs; the overlap map adds the ghost dofs touched by the rank's elements.
//
// Linked nodes (the nodes a tie's equations join, TieEquations.hpp) are owned together, by the
// lowest rank among the elements of any of them, and a rank that touches one of them holds all
// of them in its overlap: a tie's eliminated rows then combine on one rank (LinearConstraints).
#include "base/LinearAlgebra.hpp"
#include "core/mesh/Mesh.hpp"
#include "core/problem/ElementPartition.hpp"

#include <Teuchos_RCP.hpp>

#include <cstdint>
#include <vector>

namespace contactlab {

class DofMap {
 public:
  DofMap(const Mesh& mesh, const std::vector<int>& elementRank,
         const Teuchos::RCP<const Comm>& comm,
         const std::vector<std::vector<std::int64_t>>& linkedNodes = {});

  int dim() const { return dim_; }
  const Teuchos::RCP<const Map>& ownedMap() const { return ownedMap_; }
  const Teuchos::RCP<const Map>& overlapMap() const { return overlapMap_; }
  const Teuchos::RCP<const Comm>& comm() const { return comm_; }
  GO numGlobalDofs() const { return static_cast<GO>(ownedMap_->getGlobalNumElements()); }

  // Elements assembled by this rank.
  const std::vector<ElementRef>& localElements() const { return localElements_; }
  // Mesh nodes of the overlap map in overlap order (owned first); 3*i.. are dof LIDs i*dim..
  const std::vector<std::int64_t>& overlapNodes() const { return overlapNodes_; }
  std::size_t numOwnedNodes() const { return numOwnedNodes_; }
  // Overlap-local node index of a mesh node, or -1 when the node is not on this rank.
  int overlapNodeIndex(std::int64_t meshNode) const { return overlapIndex_[meshNode]; }
  // Rank owning a mesh node (-1: node used by no element).
  int nodeOwner(std::int64_t meshNode) const { return owner_[meshNode]; }
  // Global node number after renumbering (-1: node used by no element).
  GO globalNode(std::int64_t meshNode) const { return globalNode_[meshNode]; }

 private:
  int dim_;
  Teuchos::RCP<const Comm> comm_;
  Teuchos::RCP<const Map> ownedMap_, overlapMap_;
  std::vector<ElementRef> localElements_;
  std::vector<int> owner_;
  std::vector<GO> globalNode_;
  std::vector<std::int64_t> overlapNodes_;
  std::vector<int> overlapIndex_;
  std::size_t numOwnedNodes_ = 0;
};

}  // namespace contactlab
