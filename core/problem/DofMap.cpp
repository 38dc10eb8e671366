#include "core/problem/DofMap.hpp"

#include <algorithm>

namespace contactlab {

DofMap::DofMap(const Mesh& mesh, const std::vector<int>& elementRank,
               const Teuchos::RCP<const Comm>& comm,
               const std::vector<std::vector<std::int64_t>>& linkedNodes)
    : dim_(mesh.dim), comm_(comm) {
  const int rank = comm->getRank(), size = comm->getSize();
  const std::size_t nn = mesh.numNodes();
  const auto refs = allElements(mesh);

  // Owner: lowest rank among the node's elements. Every rank computes the same from the
  // global mesh, so no communication is needed.
  owner_.assign(nn, -1);
  std::vector<char> touched(nn, 0);
  for (std::size_t e = 0; e < refs.size(); ++e) {
    const auto& block = mesh.blocks[refs[e].block];
    const int npc = block.nodesPerCell();
    const int r = elementRank[e];
    for (int a = 0; a < npc; ++a) {
      const auto n = block.nodes[refs[e].cell * npc + a];
      if (owner_[n] < 0 || r < owner_[n]) owner_[n] = r;
      if (r == rank) touched[n] = 1;
    }
    if (r == rank) localElements_.push_back(refs[e]);
  }
  for (const auto& nodes : linkedNodes) {
    int owner = -1;
    bool touches = false;
    for (auto n : nodes) {
      if (owner_[n] >= 0 && (owner < 0 || owner_[n] < owner)) owner = owner_[n];
      touches = touches || touched[n];
    }
    for (auto n : nodes) {
      if (owner_[n] >= 0) owner_[n] = owner;  // a node no element uses stays without dofs
      if (touches) touched[n] = owner_[n] >= 0;
    }
  }

  // Renumber: nodes of rank 0 first (in mesh order), then rank 1, ...
  std::vector<GO> firstOfRank(size + 1, 0);
  for (std::size_t n = 0; n < nn; ++n)
    if (owner_[n] >= 0) ++firstOfRank[owner_[n] + 1];
  for (int r = 0; r < size; ++r)
    firstOfRank[r + 1] += firstOfRank[r];
  std::vector<GO> next(firstOfRank.begin(), firstOfRank.end() - 1);
  globalNode_.assign(nn, -1);
  for (std::size_t n = 0; n < nn; ++n)
    if (owner_[n] >= 0) globalNode_[n] = next[owner_[n]]++;

  // Overlap: owned nodes first, then ghosts sorted by global number.
  std::vector<std::int64_t> ghosts;
  for (std::size_t n = 0; n < nn; ++n) {
    if (owner_[n] == rank)
      overlapNodes_.push_back(static_cast<std::int64_t>(n));
    else if (touched[n])
      ghosts.push_back(static_cast<std::int64_t>(n));
  }
  numOwnedNodes_ = overlapNodes_.size();
  std::sort(ghosts.begin(), ghosts.end(),
            [&](std::int64_t a, std::int64_t b) { return globalNode_[a] < globalNode_[b]; });
  overlapNodes_.insert(overlapNodes_.end(), ghosts.begin(), ghosts.end());
  overlapIndex_.assign(nn, -1);
  for (std::size_t i = 0; i < overlapNodes_.size(); ++i)
    overlapIndex_[overlapNodes_[i]] = i;

  const GO numGlobalDofs = firstOfRank[size] * dim_;
  ownedMap_ = Teuchos::rcp(new Map(numGlobalDofs, numOwnedNodes_ * dim_, 0, comm));
  std::vector<GO> gids;
  gids.reserve(overlapNodes_.size() * dim_);
  for (auto n : overlapNodes_)
    for (int c = 0; c < dim_; ++c)
      gids.push_back(globalNode_[n] * dim_ + c);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  overlapMap_ = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(gids), 0, comm));
}

}  // namespace contactlab
