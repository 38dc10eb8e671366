#include "core/problem/ElementPartition.hpp"

#include <metis.h>

#include <stdexcept>
#include <string>

namespace contactlab {
std::vector<ElementRef> allElements(const Mesh& mesh) {
  std::vector<ElementRef> refs;
  refs.reserve(mesh.numElements());
  for (int b = 0; b < static_cast<int>(mesh.blocks.size()); ++b)
    for (std::size_t c = 0; c < mesh.blocks[b].size(); ++c)
      refs.push_back({b, c});
  return refs;
}

std::vector<int> partitionElements(const Mesh& mesh, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const auto refs = allElements(mesh);
  std::vector<int> part(refs.size(), 0);
  if (size == 1) return part;

  if (rank == 0) {
    std::vector<idx_t> eptr{0}, eind;
    for (const auto& r : refs) {
      const auto& block = mesh.blocks[r.block];
      const int npc = block.nodesPerCell();
      for (int a = 0; a < cornerCount(block.type); ++a)
        eind.push_back(static_cast<idx_t>(block.nodes[r.cell * npc + a]));
      eptr.push_back(static_cast<idx_t>(eind.size()));
    }
    idx_t ne = static_cast<idx_t>(refs.size()), nn = static_cast<idx_t>(mesh.numNodes());
    idx_t ncommon = mesh.dim, nparts = size, objval = 0;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_SEED] = 1;  // same partition on every run
    std::vector<idx_t> epart(ne), npart(nn);
    const int status =
        METIS_PartMeshDual(&ne, &nn, eptr.data(), eind.data(), nullptr, nullptr, &ncommon, &nparts,
                           nullptr, options, &objval, epart.data(), npart.data());
    if (status != METIS_OK)
      throw std::runtime_error("METIS could not partition the mesh into " + std::to_string(size) +
                               " parts (status " + std::to_string(status) + ")");
    for (std::size_t e = 0; e < refs.size(); ++e)
      part[e] = static_cast<int>(epart[e]);
  }
  MPI_Bcast(part.data(), static_cast<int>(part.size()), MPI_INT, 0, comm);
  return part;
}

}  // namespace contactlab
