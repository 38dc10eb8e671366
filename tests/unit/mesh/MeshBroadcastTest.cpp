#include "core/mesh/MeshBroadcast.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <mpi.h>

#include <cstring>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

// FNV-1a over everything a Mesh holds, to compare copies across ranks.
std::uint64_t fingerprint(const Mesh& m) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](const void* p, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
      h = (h ^ static_cast<const unsigned char*>(p)[i]) * 1099511628211ull;
  };
  mix(&m.dim, sizeof m.dim);
  mix(m.source.data(), m.source.size());
  mix(m.coords.data(), m.coords.size() * sizeof(double));
  mix(m.nodeTags.data(), m.nodeTags.size() * sizeof(std::int64_t));
  for (const auto* list : {&m.blocks, &m.boundaries}) {
    const std::size_t n = list->size();
    mix(&n, sizeof n);
    for (const auto& g : *list) {
      mix(g.name.data(), g.name.size());
      mix(&g.dim, sizeof g.dim);
      mix(&g.type, sizeof g.type);
      mix(g.nodes.data(), g.nodes.size() * sizeof(std::int64_t));
      mix(g.tags.data(), g.tags.size() * sizeof(std::int64_t));
    }
  }
  return h;
}

void expectIdenticalOnAllRanks(const Mesh& m) {
  const auto mine = static_cast<unsigned long long>(fingerprint(m));
  unsigned long long lo = 0, hi = 0;
  MPI_Allreduce(&mine, &lo, 1, MPI_UNSIGNED_LONG_LONG, MPI_MIN, MPI_COMM_WORLD);
  MPI_Allreduce(&mine, &hi, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_EQ(lo, hi);
}

TEST(MeshBroadcast, EveryRankGetsRootsMesh) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  for (int root : {0, size - 1}) {
    Mesh mesh;
    if (rank == root) {
      StackedBlocks3DParams p;  // gmsh runs on the root only
      p.elementType = "hex20";
      mesh = generateStackedBlocks3D(p);
    } else {
      mesh.dim = 2;  // stale content must be replaced
      mesh.coords = {1, 2, 3};
      mesh.blocks.resize(3);
    }
    broadcastMesh(mesh, MPI_COMM_WORLD, root);
    EXPECT_EQ(mesh.dim, 3);
    EXPECT_EQ(mesh.blockNames(), (std::vector<std::string>{"lower", "upper"}));
    EXPECT_EQ(mesh.numElements(), 8u + 27u);
    EXPECT_EQ(mesh.boundaryNodes("upper-top").size(), 7u * 7u - 9u);
    expectIdenticalOnAllRanks(mesh);
  }
}

// A file's node tags travel with the mesh: every rank names the nodes as the file does.
TEST(MeshBroadcast, NodeTagsTravel) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  Mesh mesh;
  if (rank == 0) {
    mesh = generateRectangle(RectangleParams{});
    mesh.nodeTags.resize(mesh.numNodes());
    for (std::size_t i = 0; i < mesh.numNodes(); ++i)
      mesh.nodeTags[i] = 1000 + 7 * static_cast<std::int64_t>(i);
  }
  broadcastMesh(mesh, MPI_COMM_WORLD, 0);
  ASSERT_EQ(mesh.nodeTags.size(), mesh.numNodes());
  EXPECT_EQ(mesh.nodeId(3), 1021);
  expectIdenticalOnAllRanks(mesh);
}

}  // namespace
}  // namespace contactlab
