#include "core/mesh/Mesh.hpp"

#include <algorithm>
#include <stdexcept>

namespace contactlab {
namespace {

std::vector<const CellGroup*> findIn(const std::vector<CellGroup>& groups,
                                     const std::string& name) {
  std::vector<const CellGroup*> found;
  for (const auto& g : groups)
    if (g.name == name) found.push_back(&g);
  return found;
}

std::vector<std::string> namesOf(const std::vector<CellGroup>& groups) {
  std::vector<std::string> names;
  for (const auto& g : groups)
    if (std::find(names.begin(), names.end(), g.name) == names.end()) names.push_back(g.name);
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names)
    s += (s.empty() ? "" : ", ") + n;
  return s.empty() ? "(none)" : s;
}

}  // namespace

std::size_t Mesh::numElements() const {
  std::size_t n = 0;
  for (const auto& b : blocks)
    n += b.size();
  return n;
}

std::vector<const CellGroup*> Mesh::findBlocks(const std::string& name) const {
  return findIn(blocks, name);
}

std::vector<const CellGroup*> Mesh::findBoundaries(const std::string& name) const {
  return findIn(boundaries, name);
}

std::vector<std::int64_t> Mesh::boundaryNodes(const std::string& name) const {
  auto groups = findBoundaries(name);
  if (groups.empty())
    throw std::invalid_argument("boundary group '" + name + "' is not in mesh " + source +
                                "; its boundary groups are: " + joined(boundaryNames()));
  std::vector<std::int64_t> nodes;
  for (const auto* g : groups)
    nodes.insert(nodes.end(), g->nodes.begin(), g->nodes.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

std::vector<std::string> Mesh::blockNames() const {
  return namesOf(blocks);
}
std::vector<std::string> Mesh::boundaryNames() const {
  return namesOf(boundaries);
}

}  // namespace contactlab
