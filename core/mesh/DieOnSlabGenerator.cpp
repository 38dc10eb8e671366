#include "core/mesh/GeneratorSupport.hpp"
#include "core/mesh/GmshExtract.hpp"
#include "core/mesh/GmshModel.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <gmsh.h>

#include <cmath>
#include <set>
#include <stdexcept>

namespace contactlab {
namespace {

constexpr const char* kName = "die-on-slab";

void requireDieOnSlab(const DieOnSlabParams& p) {
  const char* lengths[] = {"Slab Length", "Slab Width", "Slab Height"};
  const char* slabDivisions[] = {"Slab Divisions[0]", "Slab Divisions[1]", "Slab Divisions[2]"};
  const char* dieDivisions[] = {"Die Divisions[0]", "Die Divisions[1]", "Die Divisions[2]"};
  for (int i = 0; i < 3; ++i) {
    requirePositive(kName, lengths[i], p.slabLengths[i]);
    requireDivisions(kName, slabDivisions[i], p.slabDivisions[i]);
    requireDivisions(kName, dieDivisions[i], p.dieDivisions[i]);
  }
  requirePositive(kName, "Die Radius", p.dieRadius);
  requirePositive(kName, "Die Thickness", p.dieThickness);
  requirePositive(kName, "Die Width", p.dieWidth);
  const std::string gen = std::string(kName) + " generator: ";
  if (!(p.dieThickness < p.dieRadius))
    throw std::invalid_argument(gen + "Die Thickness = " + numberText(p.dieThickness) +
                                " must be smaller than Die Radius = " + numberText(p.dieRadius));
  if (!(p.dieAngle > 0 && p.dieAngle <= 180))
    throw std::invalid_argument(gen + "Die Angle = " + numberText(p.dieAngle) +
                                " must lie in (0, 180] degrees (the arc below the die's axis)");
  if (!(p.dieStart >= 0 && p.dieStart <= p.slabLengths[0]))
    throw std::invalid_argument(
        gen + "Die Start = " + numberText(p.dieStart) +
        " must lie on the slab, in [0, Slab Length = " + numberText(p.slabLengths[0]) + "]");
  if (!std::isfinite(p.gap) || p.gap <= -p.dieThickness)
    throw std::invalid_argument(gen + "Gap = " + numberText(p.gap) +
                                " must be a number larger than minus the Die Thickness");
  // An arc element spanning more than ~30 degrees would cut well inside the circle.
  const int fewest = static_cast<int>(std::ceil(p.dieAngle / 30.0 - 1e-12));
  if (p.dieDivisions[2] < fewest)
    throw std::invalid_argument(gen + "Die Divisions[2] = " + std::to_string(p.dieDivisions[2]) +
                                " must be at least " + std::to_string(fewest) +
                                " for Die Angle = " + numberText(p.dieAngle) +
                                ": an element spans at most 30 degrees");
}

}  // namespace

// The die is meshed as a structured box in index space, (s, y, t) in [0, nr] x [0, width] x
// [0, na], far from the slab (the two OCC volumes are never fragmented: disjoint nodes), and
// then bent onto the shell segment: s -> radius, t -> angle. Grid lines s = const become arcs
// and t = const radial rays, so order-2 nodes (half-integer s or t) land on the rays'
// midpoints and exactly on the arcs, and the map's Jacobian is positive (outward radius, y,
// increasing angle form a right-handed frame).
Mesh generateDieOnSlab(const DieOnSlabParams& p) {
  using ET = ElementType;
  const auto spec =
      elementSpec(kName, p.elementType, {ET::Tet4, ET::Tet10, ET::Hex8, ET::Hex20, ET::Hex27});
  requireDieOnSlab(p);
  const auto [length, width, height] = p.slabLengths;
  const auto [nr, nw, na] = p.dieDivisions;
  const std::string source =
      "generated die on slab (" + p.elementType + ", slab " + std::to_string(p.slabDivisions[0]) +
      "x" + std::to_string(p.slabDivisions[1]) + "x" + std::to_string(p.slabDivisions[2]) +
      ", die " + std::to_string(nr) + "x" + std::to_string(nw) + "x" + std::to_string(na) + ")";
  // The index box sits below the slab, two slab heights clear of it.
  const std::array<double, 3> indexOrigin{0.0, 0.5 * (width - p.dieWidth), -2 * height - na};
  Mesh mesh = inGmshModel("gmsh could not generate the " + source, [&] {
    resetMeshOptions();
    const auto slab = addStructuredBox({0, 0, 0}, p.slabLengths, p.slabDivisions, !spec.simplex);
    const auto die = addStructuredBox(indexOrigin, {double(nr), p.dieWidth, double(na)},
                                      {nr, nw, na}, !spec.simplex);
    const char* slabFaces[] = {"slab-xmin", "slab-xmax",   "slab-ymin",
                               "slab-ymax", "slab-bottom", "slab-top"};
    addGroup(3, {slab.volume}, "slab");
    for (int i = 0; i < 6; ++i)
      addGroup(2, {slab.faces[i]}, slabFaces[i]);
    addGroup(3, {die.volume}, "die");
    addGroup(2, {die.faces[0]}, "die-inner");
    addGroup(2, {die.faces[1]}, "die-outer");
    addGroup(2, {die.faces[2], die.faces[3]}, "die-sides");
    addGroup(2, {die.faces[4], die.faces[5]}, "die-ends");
    gmsh::model::mesh::generate(3);
    applyOrder(spec);
    return meshFromGmshModel(source, source);
  });
  std::set<std::int64_t> dieNodes;
  for (const auto* block : mesh.findBlocks("die"))
    dieNodes.insert(block->nodes.begin(), block->nodes.end());
  const double centreX = p.dieStart, centreZ = height + p.gap + p.dieRadius;
  const double inner = p.dieRadius - p.dieThickness;
  for (const auto n : dieNodes) {
    double* x = &mesh.coords[3 * n];
    // Every node of a structured order-1 or order-2 grid sits at a multiple of 1/2.
    const double s = std::round(2 * (x[0] - indexOrigin[0])) / 2;
    const double t = std::round(2 * (x[2] - indexOrigin[2])) / 2;
    const double radius = inner + s / nr * p.dieThickness;
    const double angle = (t / na - 0.5) * p.dieAngle * M_PI / 180.0;  // from straight down
    x[0] = centreX + radius * std::sin(angle);
    x[2] = centreZ - radius * std::cos(angle);
  }
  return mesh;
}

}  // namespace contactlab
