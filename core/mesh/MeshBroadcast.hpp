#pragma once
// Meshes are read or generated on one rank (gmsh runs on one rank only) and then copied to all.
#include "core/mesh/Mesh.hpp"

#include <mpi.h>

namespace contactlab {

// Collective on `comm`: afterwards every rank holds an exact copy of `root`'s mesh; whatever
// the other ranks held before is replaced. Throws std::runtime_error if MPI fails.
void broadcastMesh(Mesh& mesh, MPI_Comm comm, int root);

}  // namespace contactlab
