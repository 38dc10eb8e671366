#pragma once
// Which rank assembles each element. Elements are numbered globally by concatenating the
// mesh's blocks in order. METIS (dual graph, corner nodes only) on rank 0, broadcast to all.
#include "core/mesh/Mesh.hpp"

#include <mpi.h>

#include <vector>

namespace contactlab {

struct ElementRef {
  int block;         // index in Mesh::blocks
  std::size_t cell;  // index within the block
};

// All elements of the mesh in global order.
std::vector<ElementRef> allElements(const Mesh& mesh);

// Rank of every element (global order). One rank: all zeros, METIS is not called.
std::vector<int> partitionElements(const Mesh& mesh, MPI_Comm comm);

}  // namespace contactlab
