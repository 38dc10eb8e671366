#include "core/mesh/GeneratorSupport.hpp"
#include "core/mesh/GmshExtract.hpp"
#include "core/mesh/GmshModel.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <gmsh.h>

#include <stdexcept>

namespace contactlab {
namespace {

// Blossom full-quad recombination can in principle leave triangles; never hand them out.
void requireAllQuads(const std::string& source) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> elementTags, nodeTags;
  gmsh::model::mesh::getElements(types, elementTags, nodeTags, 2);
  for (std::size_t i = 0; i < types.size(); ++i)
    if (types[i] != 3 && !elementTags[i].empty())
      throw std::runtime_error("gmsh left non-quadrilateral elements in the " + source +
                               "; change grading sizes slightly or use tri3/tri6");
}

}  // namespace

Mesh generateHalfDisc(const HalfDiscParams& p) {
  using ET = ElementType;
  const auto spec = elementSpec("half-disc", p.elementType,
                                {ET::Tri3, ET::Tri6, ET::Quad4, ET::Quad8, ET::Quad9});
  requirePositive("half-disc", "radius", p.radius);
  requireGrading("half-disc", p.grading);
  const std::string source =
      "generated half-disc (" + p.elementType + ", R = " + formatNumber(p.radius) + ", sizes " +
      formatNumber(p.grading.sizeContact) + " to " + formatNumber(p.grading.sizeFar) + ")";
  return inGmshModel("gmsh could not generate the " + source, [&] {
    namespace occ = gmsh::model::occ;
    resetMeshOptions();
    const double cx = p.centre[0], cy = p.centre[1], r = p.radius;
    // Two quarter arcs so that the contact point is a geometric vertex, hence a mesh node.
    const int centre = occ::addPoint(cx, cy, 0);
    const int contact = occ::addPoint(cx, cy - r, 0);
    const int left = occ::addPoint(cx - r, cy, 0);
    const int right = occ::addPoint(cx + r, cy, 0);
    // Counter-clockwise loop: the surface normal is +z, so the elements are too.
    const int arcRight = occ::addCircleArc(contact, centre, right);
    const int flat = occ::addLine(right, left);
    const int arcLeft = occ::addCircleArc(left, centre, contact);
    const int loop = occ::addCurveLoop({arcRight, flat, arcLeft});
    const int surface = occ::addPlaneSurface({loop});
    occ::remove({{0, centre}});
    occ::synchronize();
    addGroup(2, {surface}, "body");
    addGroup(1, {flat}, "flat");
    addGroup(1, {arcRight, arcLeft}, "curved");
    addGroup(0, {contact}, "contact-point");
    if (!spec.simplex) {
      gmsh::option::setNumber("Mesh.RecombineAll", 1);
      gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 3);  // blossom full-quad
    }
    generateGraded(2, {cx, cy - r, 0}, p.grading, 1.0);
    if (!spec.simplex) requireAllQuads(source);
    applyOrder(spec);
    return meshFromGmshModel(source, source);
  });
}

}  // namespace contactlab
