#include "core/mesh/GeneratorSupport.hpp"
#include "core/mesh/MeshGenerators.hpp"

namespace contactlab {

Mesh generateRectangle(const RectangleParams& p) {
  using ET = ElementType;
  const auto spec = elementSpec("rectangle", p.elementType,
                                {ET::Tri3, ET::Tri6, ET::Quad4, ET::Quad8, ET::Quad9});
  requirePositive("rectangle", "Lx", p.lengths[0]);
  requirePositive("rectangle", "Ly", p.lengths[1]);
  requireDivisions("rectangle", "nx", p.divisions[0]);
  requireDivisions("rectangle", "ny", p.divisions[1]);
  if (p.corners) requireConvexQuadrilateral("quadrilateral", *p.corners);
  const std::string source = "generated rectangle (" + p.elementType + ", " +
                             std::to_string(p.divisions[0]) + "x" + std::to_string(p.divisions[1]) +
                             ")";
  Mesh mesh = meshStructuredRectangle(spec, p.origin, p.lengths, p.divisions,
                                      {"bottom", "right", "top", "left"},
                                      {"corner-bl", "corner-br", "corner-tr", "corner-tl"}, source);
  // An affine map keeps straight edges straight and mid-side nodes in the middle.
  if (p.corners) {
    mapOntoQuadrilateral(mesh, p.origin, p.lengths, *p.corners);
  } else {
    for (std::size_t n = 0; n < mesh.numNodes(); ++n)
      mesh.coords[3 * n] += p.topShift * (mesh.coords[3 * n + 1] - p.origin[1]) / p.lengths[1];
  }
  return mesh;
}

}  // namespace contactlab
