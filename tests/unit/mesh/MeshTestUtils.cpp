#include "MeshTestUtils.hpp"

#include "core/mesh/GmshSession.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <numeric>
#include <unistd.h>

namespace contactlab::test {
namespace {

using Vec = std::array<double, 3>;

double det3(const Vec& a, const Vec& b, const Vec& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}

Vec sub(const Vec& a, const Vec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

// Jacobian determinants and weights at 2x2(x2) Gauss points of the corner map.
std::vector<std::pair<double, double>> cornerJacobians(const Mesh& mesh, const CellGroup& g,
                                                       std::size_t c) {
  const auto* n = &g.nodes[c * g.nodesPerCell()];
  auto x = [&](int i) { return node(mesh, n[i]); };
  switch (g.type) {
    case ElementType::Tri3:
    case ElementType::Tri6: {
      const Vec a = sub(x(1), x(0)), b = sub(x(2), x(0));
      return {{a[0] * b[1] - a[1] * b[0], 0.5}};
    }
    case ElementType::Tet4:
    case ElementType::Tet10:
      return {{det3(sub(x(1), x(0)), sub(x(2), x(0)), sub(x(3), x(0))), 1.0 / 6}};
    default:
      break;
  }
  const double q = 1 / std::sqrt(3.0);
  const bool hex = g.dim == 3;
  // Corner reference coordinates in gmsh order.
  const int ref[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                         {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const int corners = hex ? 8 : 4;
  std::vector<std::pair<double, double>> out;
  for (int gp = 0; gp < (hex ? 8 : 4); ++gp) {
    const double xi[3] = {ref[gp][0] * q, ref[gp][1] * q, ref[gp][2] * q};
    double jac[3][3] = {};  // jac[i][j] = d x_i / d xi_j
    for (int k = 0; k < corners; ++k) {
      const Vec p = x(k);
      for (int j = 0; j < (hex ? 3 : 2); ++j) {
        double d = ref[k][j] * 0.5;
        for (int m = 0; m < (hex ? 3 : 2); ++m)
          if (m != j) d *= 0.5 * (1 + ref[k][m] * xi[m]);
        for (int i = 0; i < 3; ++i)
          jac[i][j] += p[i] * d;
      }
    }
    const double det =
        hex ? det3({jac[0][0], jac[1][0], jac[2][0]}, {jac[0][1], jac[1][1], jac[2][1]},
                   {jac[0][2], jac[1][2], jac[2][2]})
            : jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0];
    out.emplace_back(det, 1.0);
  }
  return out;
}

}  // namespace

std::array<double, 3> node(const Mesh& mesh, std::int64_t n) {
  return {mesh.coords[3 * n], mesh.coords[3 * n + 1], mesh.coords[3 * n + 2]};
}

double cellMeasure(const Mesh& mesh, const CellGroup& g, std::size_t c) {
  double sum = 0;
  for (const auto& [det, w] : cornerJacobians(mesh, g, c))
    sum += det * w;
  return sum;
}

double minCornerJacobian(const Mesh& mesh, const CellGroup& g, std::size_t c) {
  double m = 1e300;
  for (const auto& jw : cornerJacobians(mesh, g, c))
    m = std::min(m, jw.first);
  return m;
}

double blockMeasure(const Mesh& mesh, const std::string& name) {
  double sum = 0;
  for (const auto* g : mesh.findBlocks(name))
    for (std::size_t c = 0; c < g->size(); ++c)
      sum += cellMeasure(mesh, *g, c);
  return sum;
}

double minJacobian(const Mesh& mesh) {
  double m = 1e300;
  for (const auto& g : mesh.blocks)
    for (std::size_t c = 0; c < g.size(); ++c)
      m = std::min(m, minCornerJacobian(mesh, g, c));
  return m;
}

std::vector<GeneratorCase> generatorCases2D(std::size_t quads, std::size_t linearNodes,
                                            std::size_t serendipityNodes,
                                            std::size_t completeNodes) {
  using ET = ElementType;
  return {{"tri3", ET::Tri3, ET::Line2, 2 * quads, linearNodes},
          {"tri6", ET::Tri6, ET::Line3, 2 * quads, completeNodes},
          {"quad4", ET::Quad4, ET::Line2, quads, linearNodes},
          {"quad8", ET::Quad8, ET::Line3, quads, serendipityNodes},
          {"quad9", ET::Quad9, ET::Line3, quads, completeNodes}};
}

void expectGeneratedBlock(const Mesh& mesh, const GeneratorCase& c, int dim) {
  EXPECT_EQ(mesh.dim, dim);
  EXPECT_EQ(mesh.numNodes(), c.nodes);
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].name, "body");
  EXPECT_EQ(mesh.blocks[0].type, c.cellType);
  EXPECT_EQ(mesh.numElements(), c.cells);
  EXPECT_GT(minJacobian(mesh), 0.0);
}

void expectCoordinate(const Mesh& mesh, const std::string& group, int component, double value) {
  for (auto n : mesh.boundaryNodes(group))
    EXPECT_NEAR(node(mesh, n)[component], value, 1e-12) << group << " node " << n;
}

std::set<std::int64_t> blockNodes(const Mesh& mesh, const std::string& name) {
  std::set<std::int64_t> nodes;
  for (const auto* g : mesh.findBlocks(name))
    nodes.insert(g->nodes.begin(), g->nodes.end());
  return nodes;
}

std::size_t cellCount(const std::vector<const CellGroup*>& groups) {
  std::size_t n = 0;
  for (const auto* g : groups)
    n += g->size();
  return n;
}

void writeWithGmsh(const Mesh& mesh, const std::string& path, double version) {
  GmshSession session;
  gmsh::model::add("test-writer");
  std::vector<std::size_t> nodeTags(mesh.numNodes());
  std::iota(nodeTags.begin(), nodeTags.end(), 1);
  bool nodesPlaced = false;
  for (const auto* list : {&mesh.blocks, &mesh.boundaries}) {
    for (const auto& g : *list) {
      const int entity = gmsh::model::addDiscreteEntity(g.dim);
      if (!nodesPlaced) gmsh::model::mesh::addNodes(g.dim, entity, nodeTags, mesh.coords);
      nodesPlaced = true;
      std::vector<std::size_t> tags(g.tags.begin(), g.tags.end()), nodes;
      for (auto n : g.nodes)
        nodes.push_back(static_cast<std::size_t>(n) + 1);
      gmsh::model::mesh::addElementsByType(entity, info(g.type).gmshType, tags, nodes);
      const int physical = gmsh::model::addPhysicalGroup(g.dim, {entity});
      gmsh::model::setPhysicalName(g.dim, physical, g.name);
    }
  }
  gmsh::option::setNumber("Mesh.MshFileVersion", version);
  gmsh::option::setNumber("Mesh.SaveAll", 0);
  gmsh::option::setNumber("Mesh.Binary", 0);
  gmsh::write(path);
  gmsh::model::remove();
}

std::string freshTempDir(const std::string& name) {
  // Removed when the test binary exits, so repeated runs leave nothing behind.
  static struct Cleanup {
    std::vector<std::filesystem::path> dirs;
    ~Cleanup() {
      std::error_code ignored;
      for (const auto& d : dirs)
        std::filesystem::remove_all(d, ignored);
    }
  } cleanup;
  const auto dir = std::filesystem::temp_directory_path() /
                   ("contactlab-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  cleanup.dirs.push_back(dir);
  return dir.string();
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

}  // namespace contactlab::test
