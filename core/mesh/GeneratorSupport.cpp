#include "core/mesh/GeneratorSupport.hpp"

#include "core/mesh/GmshExtract.hpp"
#include "core/mesh/GmshModel.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace contactlab {

std::string typeList(std::initializer_list<ElementType> types) {
  std::string s;
  for (auto t : types)
    s += (s.empty() ? "" : ", ") + std::string(info(t).name);
  return s;
}

ElementSpec elementSpec(const std::string& generator, const std::string& name,
                        std::initializer_list<ElementType> allowed) {
  for (auto t : allowed) {
    if (name != info(t).name) continue;
    const bool simplex = t == ElementType::Tri3 || t == ElementType::Tri6 ||
                         t == ElementType::Tet4 || t == ElementType::Tet10;
    const bool serendipity = t == ElementType::Quad8 || t == ElementType::Hex20;
    return {t, simplex, info(t).order, serendipity};
  }
  throw std::invalid_argument(generator + " generator: element type '" + name +
                              "' is not supported; valid choices: " + typeList(allowed));
}

void requirePositive(const std::string& generator, const std::string& param, double value) {
  if (!(value > 0) || !std::isfinite(value))
    throw std::invalid_argument(generator + " generator: " + param + " = " + numberText(value) +
                                " must be a positive number");
}

ElementSpec roundBodySpec(const std::string& generator, const std::string& elementType,
                          std::initializer_list<ElementType> allowed, double radius,
                          const ContactGrading& grading) {
  const ElementSpec spec = elementSpec(generator, elementType, allowed);
  requirePositive(generator, "Radius", radius);
  requireGrading(generator, grading);
  return spec;
}

bool requireBase(const std::string& generator, const std::string& base,
                 const std::array<const char*, 2>& choices, double width, double height) {
  if (base != choices[0] && base != choices[1])
    throw std::invalid_argument(generator + ": base must be '" + choices[0] + "' or '" +
                                choices[1] + "' (got '" + base + "')");
  const bool block = base == "block";
  if (block) {
    requirePositive(generator, "base width", width);
    requirePositive(generator, "base height", height);
  }
  return block;
}

void requireDivisions(const std::string& generator, const std::string& param, int value) {
  if (value < 1)
    throw std::invalid_argument(generator + " generator: " + param + " = " + std::to_string(value) +
                                " must be at least 1");
}

void requireGrading(const std::string& generator, const ContactGrading& g) {
  requirePositive(generator, "Size Contact", g.sizeContact);
  requirePositive(generator, "Size Far", g.sizeFar);
  requirePositive(generator, "Transition Length", g.transitionLength);
  if (!(g.fineRadius >= 0))
    throw std::invalid_argument(generator + " generator: Fine Radius = " +
                                numberText(g.fineRadius) + " must not be negative");
  if (g.sizeFar < g.sizeContact)
    throw std::invalid_argument(
        generator + " generator: Size Far = " + numberText(g.sizeFar) +
        " must not be smaller than Size Contact = " + numberText(g.sizeContact));
}

void resetMeshOptions() {
  using gmsh::option::setNumber;
  // Mesh.Algorithm 8 (frontal-Delaunay for quads) crashes in gmsh 4.8.4: use 6 and recombine.
  setNumber("Mesh.Algorithm", 6);
  setNumber("Mesh.Algorithm3D", 1);
  setNumber("Mesh.RecombineAll", 0);
  setNumber("Mesh.RecombinationAlgorithm", 1);
  setNumber("Mesh.Recombine3DAll", 0);
  setNumber("Mesh.SubdivisionAlgorithm", 0);
  setNumber("Mesh.ElementOrder", 1);
  setNumber("Mesh.SecondOrderIncomplete", 0);
  setNumber("Mesh.SecondOrderLinear", 0);
  setNumber("Mesh.HighOrderOptimize", 0);
  setNumber("Mesh.MeshSizeFromPoints", 1);
  setNumber("Mesh.MeshSizeFromCurvature", 0);
  setNumber("Mesh.MeshSizeExtendFromBoundary", 1);
  setNumber("Mesh.MeshSizeMin", 0);
  setNumber("Mesh.MeshSizeMax", 1e22);
  setNumber("Mesh.MeshSizeFactor", 1);
  setNumber("Mesh.Optimize", 1);
}

void applyOrder(const ElementSpec& spec) {
  if (spec.order < 2) return;
  gmsh::option::setNumber("Mesh.SecondOrderIncomplete", spec.serendipity ? 1 : 0);
  gmsh::model::mesh::setOrder(spec.order);
}

void addGroup(int dim, const std::vector<int>& tags, const std::string& name) {
  const int tag = gmsh::model::addPhysicalGroup(dim, tags);
  gmsh::model::setPhysicalName(dim, tag, name);
}

std::array<double, 3> centerOfMass(int dim, int tag) {
  std::array<double, 3> c{};
  gmsh::model::occ::getCenterOfMass(dim, tag, c[0], c[1], c[2]);
  return c;
}

namespace {

// Index of the first `planes` entry (pairs of axis, coordinate) that `point` lies on.
int planeIndex(const std::array<double, 3>& point,
               const std::vector<std::pair<int, double>>& planes, double tol) {
  for (std::size_t i = 0; i < planes.size(); ++i)
    if (std::abs(point[planes[i].first] - planes[i].second) < tol) return static_cast<int>(i);
  throw std::logic_error("structured block: an OpenCASCADE entity lies on none of its planes");
}

// Distinct curves bounding `dimTags` (surfaces or a volume's faces).
std::vector<int> curvesOf(const gmsh::vectorpair& surfaces) {
  gmsh::vectorpair curves;
  gmsh::model::getBoundary(surfaces, curves, false, false, false);
  std::vector<int> tags;
  for (const auto& c : curves)
    tags.push_back(std::abs(c.second));
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  return tags;
}

// Transfinite curve with divisions[axis] segments, axis = direction of the straight curve.
void setCurveDivisions(int curve, const std::array<int, 3>& divisions) {
  std::array<double, 6> b{};
  gmsh::model::getBoundingBox(1, curve, b[0], b[1], b[2], b[3], b[4], b[5]);
  const std::array<double, 3> extent{b[3] - b[0], b[4] - b[1], b[5] - b[2]};
  const auto axis = std::max_element(extent.begin(), extent.end()) - extent.begin();
  gmsh::model::mesh::setTransfiniteCurve(curve, divisions[axis] + 1);
}

}  // namespace

RectangleEntities addStructuredRectangle(const std::array<double, 2>& origin,
                                         const std::array<double, 2>& lengths,
                                         const std::array<int, 2>& divisions, bool recombine) {
  namespace occ = gmsh::model::occ;
  RectangleEntities r{};
  r.surface = occ::addRectangle(origin[0], origin[1], 0, lengths[0], lengths[1]);
  occ::synchronize();
  const double tol = 1e-8 * std::max(lengths[0], lengths[1]);
  const double x1 = origin[0] + lengths[0], y1 = origin[1] + lengths[1];
  const std::vector<std::pair<int, double>> sides{{1, origin[1]}, {0, x1}, {1, y1}, {0, origin[0]}};
  for (int c : curvesOf({{2, r.surface}})) {
    r.sides[planeIndex(centerOfMass(1, c), sides, tol)] = c;
    setCurveDivisions(c, {divisions[0], divisions[1], 1});
  }
  gmsh::vectorpair points;
  gmsh::model::getBoundary({{2, r.surface}}, points, false, false, true);
  for (const auto& p : points) {
    std::vector<double> x;
    gmsh::model::getValue(0, p.second, {}, x);
    const bool right = std::abs(x[0] - x1) < tol, top = std::abs(x[1] - y1) < tol;
    r.corners[top ? (right ? 2 : 3) : (right ? 1 : 0)] = p.second;
  }
  gmsh::model::mesh::setTransfiniteSurface(r.surface);
  if (recombine) gmsh::model::mesh::setRecombine(2, r.surface);
  return r;
}

Mesh meshStructuredRectangle(const ElementSpec& spec, const std::array<double, 2>& origin,
                             const std::array<double, 2>& lengths,
                             const std::array<int, 2>& divisions,
                             const std::array<const char*, 4>& sides,
                             const std::array<const char*, 4>& corners, const std::string& source) {
  return inGmshModel("gmsh could not generate the " + source, [&] {
    resetMeshOptions();
    const auto r = addStructuredRectangle(origin, lengths, divisions, !spec.simplex);
    addGroup(2, {r.surface}, "body");
    for (int i = 0; i < 4; ++i)
      addGroup(1, {r.sides[i]}, sides[i]);
    for (int i = 0; i < 4; ++i)
      addGroup(0, {r.corners[i]}, corners[i]);
    gmsh::model::mesh::generate(2);
    applyOrder(spec);
    return meshFromGmshModel(source, source);
  });
}

BoxEntities addStructuredBox(const std::array<double, 3>& origin,
                             const std::array<double, 3>& lengths,
                             const std::array<int, 3>& divisions, bool recombine) {
  namespace occ = gmsh::model::occ;
  BoxEntities b{};
  b.volume = occ::addBox(origin[0], origin[1], origin[2], lengths[0], lengths[1], lengths[2]);
  occ::synchronize();
  const double tol = 1e-8 * *std::max_element(lengths.begin(), lengths.end());
  std::vector<std::pair<int, double>> planes;
  for (int axis = 0; axis < 3; ++axis) {
    planes.emplace_back(axis, origin[axis]);
    planes.emplace_back(axis, origin[axis] + lengths[axis]);
  }
  gmsh::vectorpair faces;
  gmsh::model::getBoundary({{3, b.volume}}, faces, false, false, false);
  for (auto& f : faces)
    f.second = std::abs(f.second);
  for (const auto& f : faces)
    b.faces[planeIndex(centerOfMass(2, f.second), planes, tol)] = f.second;
  for (int c : curvesOf(faces))
    setCurveDivisions(c, divisions);
  for (const auto& f : faces) {
    gmsh::model::mesh::setTransfiniteSurface(f.second);
    if (recombine) gmsh::model::mesh::setRecombine(2, f.second);
  }
  gmsh::model::mesh::setTransfiniteVolume(b.volume);
  if (recombine) gmsh::model::mesh::setRecombine(3, b.volume);
  return b;
}

void generateWithSize(int dim, const std::function<double(double x, double y, double z)>& size) {
  // A size callback instead of Distance/Threshold fields: the grading stays plain C++ and does
  // not depend on field option names, which gmsh has renamed across versions.
  gmsh::model::mesh::setSizeCallback(
      [size](int, int, double x, double y, double z) { return size(x, y, z); });
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  try {
    gmsh::model::mesh::generate(dim);
  } catch (...) {
    gmsh::model::mesh::removeSizeCallback();
    throw;
  }
  gmsh::model::mesh::removeSizeCallback();
}

void generateGraded(int dim, const std::array<double, 3>& point, const ContactGrading& g,
                    double sizeFactor) {
  generateWithSize(dim, [point, g, sizeFactor](double x, double y, double z) {
    const double d = std::sqrt((x - point[0]) * (x - point[0]) + (y - point[1]) * (y - point[1]) +
                               (z - point[2]) * (z - point[2]));
    const double t = std::clamp((d - g.fineRadius) / g.transitionLength, 0.0, 1.0);
    return sizeFactor * (g.sizeContact + t * (g.sizeFar - g.sizeContact));
  });
}

void requireAllQuads(const std::string& source) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> elementTags, nodeTags;
  gmsh::model::mesh::getElements(types, elementTags, nodeTags, 2);
  for (std::size_t i = 0; i < types.size(); ++i)
    if (types[i] != 3 && !elementTags[i].empty())
      throw std::runtime_error("gmsh left non-quadrilateral elements in the " + source +
                               "; change grading sizes slightly or use tri3/tri6");
}

void rotateBlockAboutZ(Mesh& mesh, const std::string& name, double cx, double cy, double degrees) {
  if (degrees == 0) return;
  std::vector<std::int64_t> nodes;
  for (const auto* g : mesh.findBlocks(name))
    nodes.insert(nodes.end(), g->nodes.begin(), g->nodes.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  const double a = degrees * M_PI / 180, c = std::cos(a), s = std::sin(a);
  for (auto n : nodes) {
    double& x = mesh.coords[3 * n];
    double& y = mesh.coords[3 * n + 1];
    const double dx = x - cx, dy = y - cy;
    x = cx + c * dx - s * dy;
    y = cy + s * dx + c * dy;
  }
}

void requireConvexQuadrilateral(const std::string& generator, const std::array<double, 8>& c) {
  for (int k = 0; k < 4; ++k) {
    const int a = k, b = (k + 1) % 4, d = (k + 2) % 4;
    const double turn = (c[2 * b] - c[2 * a]) * (c[2 * d + 1] - c[2 * b + 1]) -
                        (c[2 * b + 1] - c[2 * a + 1]) * (c[2 * d] - c[2 * b]);
    if (!(turn > 0))
      throw std::invalid_argument(generator +
                                  ": the corners must list a convex quadrilateral "
                                  "counter-clockwise (bottom-left, bottom-right, top-right, "
                                  "top-left)");
  }
}

void mapOntoQuadrilateral(Mesh& mesh, const std::array<double, 2>& origin,
                          const std::array<double, 2>& lengths,
                          const std::array<double, 8>& corners) {
  for (std::size_t n = 0; n < mesh.numNodes(); ++n) {
    double* x = &mesh.coords[3 * n];
    const double xi = (x[0] - origin[0]) / lengths[0], eta = (x[1] - origin[1]) / lengths[1];
    const double N[4] = {(1 - xi) * (1 - eta), xi * (1 - eta), xi * eta, (1 - xi) * eta};
    x[0] = x[1] = 0.0;
    for (int c = 0; c < 4; ++c)
      for (int i = 0; i < 2; ++i)
        x[i] += N[c] * corners[2 * c + i];
  }
}

}  // namespace contactlab
