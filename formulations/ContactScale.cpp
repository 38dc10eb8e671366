#include "formulations/ContactScale.hpp"

#include "core/materials/ReferenceStiffness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace contactlab {

namespace {

double distance(const Mesh& mesh, std::int64_t a, std::int64_t b) {
  double d2 = 0;
  for (int k = 0; k < 3; ++k) {
    const double d = mesh.coords[3 * a + k] - mesh.coords[3 * b + k];
    d2 += d * d;
  }
  return std::sqrt(d2);
}

// Mean corner-to-corner edge length of each facet of the group (a line's length in 2D).
std::vector<double> facetSizes(const Mesh& mesh, const std::string& group) {
  std::vector<double> sizes;
  for (const CellGroup* g : mesh.findBoundaries(group)) {
    const int corners = cornerCount(g->type), stride = g->nodesPerCell();
    if (corners < 2) continue;
    for (std::size_t c = 0; c < g->size(); ++c) {
      const std::int64_t* n = g->nodes.data() + c * static_cast<std::size_t>(stride);
      // A line has one edge; a polygon's corners close the loop.
      const int edges = corners == 2 ? 1 : corners;
      double sum = 0;
      for (int e = 0; e < edges; ++e)
        sum += distance(mesh, n[e], n[(e + 1) % corners]);
      sizes.push_back(sum / edges);
    }
  }
  return sizes;
}

// Blocks with a node of the boundary group.
std::set<std::string> blocksBounded(const Mesh& mesh, const std::string& group) {
  const std::vector<std::int64_t> nodes = mesh.boundaryNodes(group);
  std::set<std::string> names;
  for (const CellGroup& block : mesh.blocks) {
    if (names.count(block.name)) continue;
    for (std::int64_t n : block.nodes)
      if (std::binary_search(nodes.begin(), nodes.end(), n)) {
        names.insert(block.name);
        break;
      }
  }
  return names;
}

}  // namespace

ContactScale contactScale(const Mesh& mesh,
                          const std::map<std::string, std::shared_ptr<const Material>>& materials,
                          const std::string& slave, const std::string& master) {
  std::set<std::string> blocks = blocksBounded(mesh, slave);
  if (!master.empty())
    for (const std::string& b : blocksBounded(mesh, master))
      blocks.insert(b);
  ContactScale scale;
  scale.youngModulus = std::numeric_limits<double>::infinity();
  for (const std::string& b : blocks) {
    const auto it = materials.find(b);
    if (it == materials.end() || !it->second) continue;
    scale.youngModulus = std::min(scale.youngModulus, referenceYoungModulus(*it->second));
  }
  if (!std::isfinite(scale.youngModulus))
    throw std::invalid_argument("no block bounded by the contact surfaces has a material");
  std::vector<double> sizes = facetSizes(mesh, slave);
  if (sizes.empty()) throw std::invalid_argument("the slave surface '" + slave + "' has no facets");
  const auto middle = sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2);
  std::nth_element(sizes.begin(), middle, sizes.end());
  scale.facetSize = *middle;
  if (!(scale.facetSize > 0))
    throw std::invalid_argument("the slave surface '" + slave + "' has facets of zero size");
  return scale;
}

std::string coefficientAdvice(const std::string& key, double value, double automatic) {
  if (!(value > 0) || !(automatic > 0)) return "";
  const double ratio = value / automatic;
  if (ratio >= 0.1 && ratio <= 10) return "";
  std::ostringstream text;
  text << key << " = " << value;
  text.precision(2);
  text << " is " << (ratio < 1 ? "1/" : "") << std::scientific << (ratio < 1 ? 1 / ratio : ratio)
       << (ratio < 1 ? " of" : " times") << " the model's scale " << automatic
       << ": set it to 0 (automatic) or within a decade of that";
  return text.str();
}

}  // namespace contactlab
