#include "core/mesh/GmshExtract.hpp"

#include "core/mesh/FacetOrientation.hpp"
#include "core/mesh/MeshChecks.hpp"

#include <gmsh.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>

namespace contactlab {
namespace {

std::string groupName(int dim, int tag) {
  std::string name;
  gmsh::model::getPhysicalName(dim, tag, name);
  if (!name.empty()) return name;
  static const char* kinds[] = {"point", "curve", "surface", "volume"};
  return std::string(kinds[dim]) + "-" + std::to_string(tag);
}

// Cells of one physical group, connectivity still in gmsh node tags.
std::vector<CellGroup> readGroup(int dim, int tag, const std::string& label) {
  const std::string name = groupName(dim, tag);
  std::map<ElementType, CellGroup> byType;  // ordered by ElementType for a stable result
  std::vector<int> entities;
  gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
  for (int entity : entities) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> elementTags, nodeTags;
    gmsh::model::mesh::getElements(types, elementTags, nodeTags, dim, entity);
    for (std::size_t i = 0; i < types.size(); ++i) {
      ElementType type;
      try {
        type = elementTypeFromGmsh(types[i]);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(label + ", physical group '" + name + "': " + e.what());
      }
      auto& g = byType[type];
      g.name = name;
      g.dim = dim;
      g.type = type;
      g.tags.insert(g.tags.end(), elementTags[i].begin(), elementTags[i].end());
      g.nodes.insert(g.nodes.end(), nodeTags[i].begin(), nodeTags[i].end());
    }
  }
  std::vector<CellGroup> groups;
  for (auto& entry : byType)
    groups.push_back(std::move(entry.second));
  return groups;
}

// Renumbers connectivity from gmsh tags to 0..n-1 and fills the coordinates; returns the tags
// of nodes 0..n-1.
std::vector<std::int64_t> renumberNodes(Mesh& mesh, const std::string& label) {
  std::vector<std::int64_t> used;
  for (auto* list : {&mesh.blocks, &mesh.boundaries})
    for (const auto& g : *list)
      used.insert(used.end(), g.nodes.begin(), g.nodes.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  auto index = [&](std::int64_t tag) {
    return std::lower_bound(used.begin(), used.end(), tag) - used.begin();
  };
  for (auto* list : {&mesh.blocks, &mesh.boundaries})
    for (auto& g : *list)
      for (auto& n : g.nodes)
        n = index(n);

  std::vector<std::size_t> tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(tags, coords, parametric, -1, -1, false, false);
  std::vector<bool> found(used.size(), false);
  mesh.coords.assign(3 * used.size(), 0.0);
  for (std::size_t i = 0; i < tags.size(); ++i) {
    const auto tag = static_cast<std::int64_t>(tags[i]);
    const auto k = index(tag);
    if (k == static_cast<std::ptrdiff_t>(used.size()) || used[k] != tag) continue;
    std::copy_n(&coords[3 * i], 3, &mesh.coords[3 * k]);
    found[k] = true;
  }
  const auto missing = std::find(found.begin(), found.end(), false);
  if (missing != found.end())
    throw std::runtime_error(label + " uses node " + std::to_string(used[missing - found.begin()]) +
                             " in an element but does not define its coordinates");
  return used;
}

}  // namespace

Mesh meshFromGmshModel(const std::string& source, const std::string& label, NodeIds ids) {
  gmsh::vectorpair physicals;
  gmsh::model::getPhysicalGroups(physicals);
  if (physicals.empty())
    throw std::runtime_error(label +
                             " has no physical groups; contactlab takes element blocks and "
                             "boundaries from (named) physical groups only");
  Mesh mesh;
  mesh.source = source;
  for (const auto& p : physicals)
    mesh.dim = std::max(mesh.dim, p.first);
  if (mesh.dim < 2)
    throw std::runtime_error(label +
                             " has no 2D or 3D physical group; the element blocks must be a "
                             "physical surface (2D) or physical volume (3D)");
  // Boundaries listed facets first: they are the ones scenes refer to most.
  std::stable_sort(physicals.begin(), physicals.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [dim, tag] : physicals) {
    auto& list = dim == mesh.dim ? mesh.blocks : mesh.boundaries;
    for (auto& g : readGroup(dim, tag, label))
      list.push_back(std::move(g));
  }
  if (mesh.blocks.empty())
    throw std::runtime_error(label + " has physical groups of dimension " +
                             std::to_string(mesh.dim) + " but they contain no elements");
  std::vector<std::int64_t> tags = renumberNodes(mesh, label);
  if (ids == NodeIds::gmshTags) mesh.nodeTags = std::move(tags);
  checkMesh(mesh);
  orientBoundaryFacets(mesh);
  return mesh;
}

}  // namespace contactlab
