// Problem's checkpoint hooks: its converged state gathered on rank 0 in mesh order, and set back
// from the whole of it on every rank (a run continued on another number of ranks reads the
// same file).
#include "base/GatherOnRoot.hpp"
#include "base/InputError.hpp"
#include "core/problem/CollectiveError.hpp"
#include "core/problem/Problem.hpp"

namespace contactlab {
namespace {

std::vector<std::int64_t> blockStarts(const Mesh& mesh) {
  std::vector<std::int64_t> starts(mesh.blocks.size() + 1, 0);
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b)
    starts[b + 1] = starts[b] + static_cast<std::int64_t>(mesh.blocks[b].size());
  return starts;
}

}  // namespace

std::vector<double> Problem::gatherDisplacements(const Vector& u) const {
  const int d = dim();
  const std::size_t owned = dofs_->numOwnedNodes();
  std::vector<std::int64_t> nodes(dofs_->overlapNodes().begin(),
                                  dofs_->overlapNodes().begin() + owned);
  auto data = u.getData(0);
  std::vector<double> values(data.begin(), data.begin() + owned * d);
  const MPI_Comm comm = rawMpiComm(comm_);
  const std::vector<std::int64_t> allNodes = gatherOnRoot(nodes, MPI_INT64_T, comm);
  const std::vector<double> allValues = gatherOnRoot(values, MPI_DOUBLE, comm);
  if (comm_->getRank() != 0) return {};
  std::vector<double> out(model_.mesh->numNodes() * d, 0.0);
  for (std::size_t i = 0; i < allNodes.size(); ++i)
    for (int c = 0; c < d; ++c)
      out[allNodes[i] * d + c] = allValues[i * d + c];
  return out;
}

void Problem::scatterDisplacements(const std::vector<double>& all, Vector& u) const {
  const int d = dim();
  if (all.size() != model_.mesh->numNodes() * d)
    throw InputError("the checkpoint has " + std::to_string(all.size() / d) +
                     " nodes' displacements, the mesh " + std::to_string(model_.mesh->numNodes()) +
                     " nodes");
  auto data = u.getDataNonConst(0);
  for (std::size_t i = 0; i < dofs_->numOwnedNodes(); ++i)
    for (int c = 0; c < d; ++c)
      data[i * d + c] = all[dofs_->overlapNodes()[i] * d + c];
}

ElementStates Problem::gatherElementStates() const {
  const std::vector<std::int64_t> starts = blockStarts(*model_.mesh);
  // Per local element: its global index and state size, then the values.
  std::vector<std::int64_t> index, sizes;
  std::vector<double> values;
  for (const LocalElement& e : elements_) {
    index.push_back(starts[e.block] + static_cast<std::int64_t>(e.cell));
    sizes.push_back(static_cast<std::int64_t>(e.stateOld.size()));
    values.insert(values.end(), e.stateOld.begin(), e.stateOld.end());
  }
  const MPI_Comm comm = rawMpiComm(comm_);
  const std::vector<std::int64_t> allIndex = gatherOnRoot(index, MPI_INT64_T, comm);
  const std::vector<std::int64_t> allSizes = gatherOnRoot(sizes, MPI_INT64_T, comm);
  const std::vector<double> allValues = gatherOnRoot(values, MPI_DOUBLE, comm);
  ElementStates out;
  if (comm_->getRank() != 0) return out;
  // Reorder from rank order to global element order.
  const std::size_t n = static_cast<std::size_t>(starts.back());
  std::vector<std::int64_t> from(n, -1), size(n, 0);
  for (std::size_t i = 0, at = 0; i < allIndex.size(); at += allSizes[i], ++i) {
    from[allIndex[i]] = static_cast<std::int64_t>(at);
    size[allIndex[i]] = allSizes[i];
  }
  out.offsets.assign(n + 1, 0);
  for (std::size_t k = 0; k < n; ++k)
    out.offsets[k + 1] = out.offsets[k] + size[k];
  out.values.reserve(allValues.size());
  for (std::size_t k = 0; k < n; ++k)
    out.values.insert(out.values.end(), allValues.begin() + from[k],
                      allValues.begin() + from[k] + size[k]);
  return out;
}

void Problem::setElementStates(const ElementStates& states) {
  const std::vector<std::int64_t> starts = blockStarts(*model_.mesh);
  if (states.offsets.size() != static_cast<std::size_t>(starts.back()) + 1)
    throw InputError("the checkpoint has the internal variables of " +
                     std::to_string(states.offsets.empty() ? 0 : states.offsets.size() - 1) +
                     " elements, the mesh " + std::to_string(starts.back()) + " elements");
  // A mismatch is found on the rank of its element: every rank throws (agreeOnError).
  std::string mismatch;
  for (LocalElement& e : elements_) {
    if (!mismatch.empty()) break;
    const std::int64_t k = starts[e.block] + static_cast<std::int64_t>(e.cell);
    const std::int64_t size = states.offsets[k + 1] - states.offsets[k];
    if (size != static_cast<std::int64_t>(e.stateOld.size())) {
      mismatch = ("the checkpoint's element " + std::to_string(k + 1) + " has " +
                  std::to_string(size) + " internal variables, this model's " +
                  std::to_string(e.stateOld.size()) + " (another material or element type)");
      continue;
    }
    std::copy(states.values.begin() + states.offsets[k],
              states.values.begin() + states.offsets[k + 1], e.stateOld.begin());
    e.stateNew = e.stateOld;
    e.plastic = false;
  }
  agreeOnError(*comm_, mismatch);
}

}  // namespace contactlab
