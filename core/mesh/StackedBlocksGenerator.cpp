#include "core/mesh/GeneratorSupport.hpp"
#include "core/mesh/GmshExtract.hpp"
#include "core/mesh/GmshModel.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <gmsh.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace contactlab {
namespace {

std::string divisionsText(const int* d, int n) {
  std::string s;
  for (int i = 0; i < n; ++i)
    s += (i ? "x" : "") + std::to_string(d[i]);
  return s;
}

// Both blocks' n division counts; returns the mesh's source, e.g. "generated stacked blocks 2D
// (quad4, lower 4x2, upper 3x2)".
std::string requireBlockDivisions(const std::string& generator, const std::string& elementType,
                                  const int* lower, const int* upper, int n) {
  for (int i = 0; i < n; ++i) {
    requireDivisions(generator, "lowerDivisions[" + std::to_string(i) + "]", lower[i]);
    requireDivisions(generator, "upperDivisions[" + std::to_string(i) + "]", upper[i]);
  }
  return "generated stacked blocks " + std::to_string(n) + "D (" + elementType + ", lower " +
         divisionsText(lower, n) + ", upper " + divisionsText(upper, n) + ")";
}

void requireStacking(const std::string& generator, double lowerHeight, double upperHeight,
                     double gap, double rotation) {
  requirePositive(generator, "Lower Height", lowerHeight);
  requirePositive(generator, "Upper Height", upperHeight);
  if (!std::isfinite(gap) || gap <= -std::min(lowerHeight, upperHeight))
    throw std::invalid_argument(generator + " generator: gap = " + numberText(gap) +
                                " must be a number larger than minus the smaller block height");
  if (!std::isfinite(rotation) || std::abs(rotation) > 45)
    throw std::invalid_argument(generator + " generator: upperRotationDeg = " +
                                numberText(rotation) + " must lie in [-45, 45] degrees");
}

}  // namespace

// The two blocks are separate OCC entities that are never fragmented, so gmsh meshes them
// independently: disjoint nodes and non-matching interface meshes.
Mesh generateStackedBlocks2D(const StackedBlocks2DParams& p) {
  using ET = ElementType;
  const std::string gen = "stacked-blocks-2d";
  const auto spec =
      elementSpec(gen, p.elementType, {ET::Tri3, ET::Tri6, ET::Quad4, ET::Quad8, ET::Quad9});
  requirePositive(gen, "width", p.width);
  requireStacking(gen, p.lowerHeight, p.upperHeight, p.gap, p.upperRotationDeg);
  const std::string source = requireBlockDivisions(gen, p.elementType, p.lowerDivisions.data(),
                                                   p.upperDivisions.data(), 2);
  // Along y the heights are the blocks' y extents; along x their x extents.
  const int along = p.alongX ? 0 : 1, across = 1 - along;
  std::array<double, 2> upperOrigin = p.origin, lowerSize, upperSize;
  upperOrigin[along] += p.lowerHeight + p.gap;
  lowerSize[along] = p.lowerHeight, lowerSize[across] = p.width;
  upperSize[along] = p.upperHeight, upperSize[across] = p.width;
  Mesh mesh = inGmshModel("gmsh could not generate the " + source, [&] {
    resetMeshOptions();
    const auto lower = addStructuredRectangle(p.origin, lowerSize, p.lowerDivisions, !spec.simplex);
    const auto upper =
        addStructuredRectangle(upperOrigin, upperSize, p.upperDivisions, !spec.simplex);
    const char* sides[] = {"bottom", "right", "top", "left"};
    for (const auto& [block, r] : {std::pair{"lower", lower}, std::pair{"upper", upper}}) {
      addGroup(2, {r.surface}, block);
      for (int i = 0; i < 4; ++i)
        addGroup(1, {r.sides[i]}, std::string(block) + "-" + sides[i]);
    }
    gmsh::model::mesh::generate(2);
    applyOrder(spec);
    return meshFromGmshModel(source, source);
  });
  rotateBlockAboutZ(mesh, "upper", upperOrigin[0] + upperSize[0] / 2,
                    upperOrigin[1] + upperSize[1] / 2, p.upperRotationDeg);
  return mesh;
}

Mesh generateStackedBlocks3D(const StackedBlocks3DParams& p) {
  using ET = ElementType;
  const std::string gen = "stacked-blocks-3d";
  const auto spec =
      elementSpec(gen, p.elementType, {ET::Tet4, ET::Tet10, ET::Hex8, ET::Hex20, ET::Hex27});
  requirePositive(gen, "footprint[0]", p.footprint[0]);
  requirePositive(gen, "footprint[1]", p.footprint[1]);
  requireStacking(gen, p.lowerHeight, p.upperHeight, p.gap, p.upperRotationDeg);
  if (!(p.upperMargin >= 0))
    throw std::invalid_argument(gen + ": upper margin must be >= 0 (got " +
                                std::to_string(p.upperMargin) + ")");
  const std::string source = requireBlockDivisions(gen, p.elementType, p.lowerDivisions.data(),
                                                   p.upperDivisions.data(), 3);
  const double upperZ = p.origin[2] + p.lowerHeight + p.gap;
  Mesh mesh = inGmshModel("gmsh could not generate the " + source, [&] {
    resetMeshOptions();
    const auto [lx, ly] = p.footprint;
    const auto lower =
        addStructuredBox(p.origin, {lx, ly, p.lowerHeight}, p.lowerDivisions, !spec.simplex);
    const double m = p.upperMargin;
    const auto upper =
        addStructuredBox({p.origin[0] - m, p.origin[1] - m, upperZ},
                         {lx + 2 * m, ly + 2 * m, p.upperHeight}, p.upperDivisions, !spec.simplex);
    const char* faces[] = {"xmin", "xmax", "ymin", "ymax", "bottom", "top"};
    for (const auto& [block, b] : {std::pair{"lower", lower}, std::pair{"upper", upper}}) {
      addGroup(3, {b.volume}, block);
      for (int i = 0; i < 6; ++i)
        addGroup(2, {b.faces[i]}, std::string(block) + "-" + faces[i]);
    }
    gmsh::model::mesh::generate(3);
    applyOrder(spec);
    return meshFromGmshModel(source, source);
  });
  rotateBlockAboutZ(mesh, "upper", p.origin[0] + p.footprint[0] / 2,
                    p.origin[1] + p.footprint[1] / 2, p.upperRotationDeg);
  return mesh;
}

}  // namespace contactlab
