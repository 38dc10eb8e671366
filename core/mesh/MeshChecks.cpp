#include "core/mesh/MeshChecks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace contactlab {
namespace {

[[noreturn]] void fail(const Mesh& mesh, const std::string& what) {
  throw std::runtime_error("mesh " + mesh.source + ": " + what);
}

void checkGroup(const Mesh& mesh, const CellGroup& g, bool block) {
  const std::string kind = block ? "block" : "boundary group";
  const auto& ti = info(g.type);
  if (ti.dim != g.dim)
    fail(mesh, kind + " '" + g.name + "' holds " + ti.name + " cells but claims dimension " +
                   std::to_string(g.dim));
  if (block ? g.dim != mesh.dim : g.dim >= mesh.dim)
    fail(mesh, kind + " '" + g.name + "' has cells of dimension " + std::to_string(g.dim) +
                   " in a " + std::to_string(mesh.dim) + "D mesh");
  if (g.nodes.size() != g.tags.size() * static_cast<std::size_t>(ti.nodes))
    fail(mesh, kind + " '" + g.name + "' has " + std::to_string(g.nodes.size()) +
                   " connectivity entries for " + std::to_string(g.tags.size()) + " " + ti.name +
                   " cells");
  const auto n = static_cast<std::int64_t>(mesh.numNodes());
  for (std::size_t i = 0; i < g.nodes.size(); ++i)
    if (g.nodes[i] < 0 || g.nodes[i] >= n)
      fail(mesh, kind + " '" + g.name + "' element " + std::to_string(g.tags[i / ti.nodes]) +
                     " references node " + std::to_string(g.nodes[i]) + " but the mesh has " +
                     std::to_string(n) + " nodes");
}

}  // namespace

void checkMesh(const Mesh& mesh) {
  if (mesh.dim != 2 && mesh.dim != 3)
    fail(mesh, "spatial dimension is " + std::to_string(mesh.dim) + " but must be 2 or 3");
  if (mesh.coords.size() % 3 != 0 || mesh.coords.empty())
    fail(mesh, "has " + std::to_string(mesh.coords.size()) +
                   " coordinate values, which is not a positive multiple of 3");
  if (mesh.blocks.empty()) fail(mesh, "has no element block (no cells of its top dimension)");
  if (!mesh.nodeTags.empty() && mesh.nodeTags.size() != mesh.numNodes())
    fail(mesh, "has " + std::to_string(mesh.nodeTags.size()) + " node tags for " +
                   std::to_string(mesh.numNodes()) + " nodes");
  double extent = 0;
  for (double c : mesh.coords) {
    if (!std::isfinite(c)) fail(mesh, "has a coordinate that is not a finite number");
    extent = std::max(extent, std::abs(c));
  }
  if (mesh.dim == 2) {
    // Relative tolerance: 2D models must lie in z = 0, up to rounding of the mesher.
    const double tol = 1e-12 * std::max(extent, 1.0);
    for (std::size_t i = 0; i < mesh.numNodes(); ++i)
      if (std::abs(mesh.coords[3 * i + 2]) > tol) {
        std::ostringstream z;
        z << mesh.coords[3 * i + 2];
        fail(mesh, "is 2D but node " + std::to_string(mesh.nodeId(static_cast<std::int64_t>(i))) +
                       " has z = " + z.str() + "; 2D meshes must lie in z = 0");
      }
  }
  for (const auto& g : mesh.blocks)
    checkGroup(mesh, g, true);
  for (const auto& g : mesh.boundaries)
    checkGroup(mesh, g, false);
}

}  // namespace contactlab
