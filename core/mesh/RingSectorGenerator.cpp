#include "core/mesh/GeneratorSupport.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace contactlab {
namespace {

constexpr const char* kGenerator = "ring-sector generator";

void requireRingSector(const RingSectorParams& p) {
  requirePositive("ring-sector", "Inner Radius", p.innerRadius);
  requirePositive("ring-sector", "Outer Radius", p.outerRadius);
  if (!(p.outerRadius > p.innerRadius))
    throw std::invalid_argument(std::string(kGenerator) +
                                ": Outer Radius = " + numberText(p.outerRadius) +
                                " must be larger than Inner Radius = " + numberText(p.innerRadius));
  if (!(p.angle > 0 && p.angle <= 360))
    throw std::invalid_argument(std::string(kGenerator) + ": Angle = " + numberText(p.angle) +
                                " must lie in (0, 360] degrees");
  requireDivisions("ring-sector", "Radial Divisions", p.radialDivisions);
  requireDivisions("ring-sector", "Circumferential Divisions", p.circumferentialDivisions);
  const int fewest = static_cast<int>(std::ceil(p.angle / 90.0 - 1e-12));
  if (p.circumferentialDivisions < fewest)
    throw std::invalid_argument(std::string(kGenerator) + ": Circumferential Divisions = " +
                                std::to_string(p.circumferentialDivisions) + " must be at least " +
                                std::to_string(fewest) + " for Angle = " + numberText(p.angle) +
                                ": an element spans at most 90 degrees");
  requirePositive("ring-sector", "Radial Grading", p.radialGrading);
}

// cos and sin of an angle in degrees, exact at multiples of 90 (nodes on the axes keep a zero
// coordinate, not 6e-17).
std::array<double, 2> direction(double degrees) {
  const double quarters = degrees / 90.0;
  if (quarters == std::round(quarters)) {
    const int k = ((static_cast<int>(std::round(quarters)) % 4) + 4) % 4;
    const double c[4] = {1, 0, -1, 0}, s[4] = {0, 1, 0, -1};
    return {c[k], s[k]};
  }
  const double a = degrees * M_PI / 180.0;
  return {std::cos(a), std::sin(a)};
}

// A closed ring: the nodes of the seam at theta = 360 degrees (grid line t = nt) become those at
// theta = 0, and the seam's groups (then interior) are dropped.
void closeRing(Mesh& mesh, const std::vector<std::array<double, 2>>& grid, int nt) {
  std::map<long, std::int64_t> seam;  // 2 s -> node at t = 0
  for (std::size_t n = 0; n < mesh.numNodes(); ++n)
    if (grid[n][1] == 0) seam[std::lround(2 * grid[n][0])] = static_cast<std::int64_t>(n);
  std::vector<std::int64_t> renumber(mesh.numNodes());
  std::vector<double> coords;
  for (std::size_t n = 0; n < mesh.numNodes(); ++n) {
    if (grid[n][1] == nt) continue;
    renumber[n] = static_cast<std::int64_t>(coords.size() / 3);
    coords.insert(coords.end(), mesh.coords.begin() + 3 * n, mesh.coords.begin() + 3 * n + 3);
  }
  for (std::size_t n = 0; n < mesh.numNodes(); ++n)
    if (grid[n][1] == nt) renumber[n] = renumber[seam.at(std::lround(2 * grid[n][0]))];
  mesh.coords = std::move(coords);
  auto& b = mesh.boundaries;
  b.erase(std::remove_if(b.begin(), b.end(),
                         [](const CellGroup& g) {
                           return g.name == "start" || g.name == "end" ||
                                  g.name == "corner-inner-end" || g.name == "corner-outer-end";
                         }),
          b.end());
  for (auto* groups : {&mesh.blocks, &mesh.boundaries})
    for (auto& g : *groups)
      for (auto& n : g.nodes)
        n = renumber[n];
}

}  // namespace

std::vector<double> ringSectorRadii(double innerRadius, double outerRadius, int divisions,
                                    double grading) {
  // Sizes h_i = h_0 q^i with h_{n-1} / h_0 = grading.
  const double q = divisions > 1 ? std::pow(grading, 1.0 / (divisions - 1)) : 1.0;
  std::vector<double> r(divisions + 1, innerRadius);
  double total = 0, h = 1;
  for (int i = 0; i < divisions; ++i, h *= q)
    total += h;
  h = (outerRadius - innerRadius) / total;
  for (int i = 1; i < divisions; ++i, h *= q)
    r[i] = r[i - 1] + h;
  r[divisions] = outerRadius;
  return r;
}

Mesh generateRingSector(const RingSectorParams& p) {
  using ET = ElementType;
  const auto spec = elementSpec("ring-sector", p.elementType,
                                {ET::Tri3, ET::Tri6, ET::Quad4, ET::Quad8, ET::Quad9});
  requireRingSector(p);
  const int nr = p.radialDivisions, nt = p.circumferentialDivisions;
  const std::string source = "generated ring sector (" + p.elementType + ", " + std::to_string(nr) +
                             "x" + std::to_string(nt) + ")";
  // A structured grid on [0, nr] x [0, nt], whose node (s, t) goes to radius r(s) (the graded
  // radii at integers, linear between them) and angle t / nt * Angle: grid lines t = const are
  // rays, s = const are circles, so mid-side nodes (half-integer s or t) lie on the rays'
  // midpoints and exactly on the arcs.
  Mesh mesh = meshStructuredRectangle(
      spec, {0.0, 0.0}, {double(nr), double(nt)}, {nr, nt}, {"start", "outer", "end", "inner"},
      {"corner-inner-start", "corner-outer-start", "corner-outer-end", "corner-inner-end"}, source);
  const auto radii = ringSectorRadii(p.innerRadius, p.outerRadius, nr, p.radialGrading);
  std::vector<std::array<double, 2>> grid(mesh.numNodes());
  for (std::size_t n = 0; n < mesh.numNodes(); ++n) {
    double* x = &mesh.coords[3 * n];
    // Every node of a structured order-1 or order-2 grid sits at a multiple of 1/2.
    const double s = std::round(2 * x[0]) / 2, t = std::round(2 * x[1]) / 2;
    grid[n] = {s, t};
    const int i = std::clamp(static_cast<int>(std::floor(s)), 0, nr - 1);
    const double radius = radii[i] + (s - i) * (radii[i + 1] - radii[i]);
    const auto d = direction(t / nt * p.angle);
    x[0] = p.centre[0] + radius * d[0];
    x[1] = p.centre[1] + radius * d[1];
  }
  if (p.angle == 360) closeRing(mesh, grid, nt);
  return mesh;
}

}  // namespace contactlab
