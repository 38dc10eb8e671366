#include "core/mesh/GeneratorSupport.hpp"
#include "core/mesh/GmshExtract.hpp"
#include "core/mesh/GmshModel.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <gmsh.h>

namespace contactlab {

Mesh generateBox(const BoxParams& p) {
  using ET = ElementType;
  const auto spec =
      elementSpec("box", p.elementType, {ET::Tet4, ET::Tet10, ET::Hex8, ET::Hex20, ET::Hex27});
  for (int i = 0; i < 3; ++i) {
    requirePositive("box", std::string("L") + "xyz"[i], p.lengths[i]);
    requireDivisions("box", std::string("n") + "xyz"[i], p.divisions[i]);
  }
  if (p.xyCorners) requireConvexQuadrilateral("box", *p.xyCorners);
  const std::string source = "generated box (" + p.elementType + ", " +
                             std::to_string(p.divisions[0]) + "x" + std::to_string(p.divisions[1]) +
                             "x" + std::to_string(p.divisions[2]) + ")";
  return inGmshModel("gmsh could not generate the " + source, [&] {
    resetMeshOptions();
    const auto b = addStructuredBox(p.origin, p.lengths, p.divisions, !spec.simplex);
    addGroup(3, {b.volume}, "body");
    const char* faces[] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
    for (int i = 0; i < 6; ++i)
      addGroup(2, {b.faces[i]}, faces[i]);
    gmsh::model::mesh::generate(3);
    applyOrder(spec);
    Mesh mesh = meshFromGmshModel(source, source);
    if (p.xyCorners)
      mapOntoQuadrilateral(mesh, {p.origin[0], p.origin[1]}, {p.lengths[0], p.lengths[1]},
                           *p.xyCorners);
    return mesh;
  });
}

}  // namespace contactlab
