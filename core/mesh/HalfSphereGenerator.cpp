#include "core/mesh/GeneratorSupport.hpp"
#include "core/mesh/GmshExtract.hpp"
#include "core/mesh/GmshModel.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <gmsh.h>

#include <cmath>
#include <string>

namespace contactlab {

Mesh generateHalfSphere(const HalfSphereParams& p) {
  using ET = ElementType;
  const auto spec =
      roundBodySpec("half-sphere", p.elementType,
                    {ET::Tet4, ET::Tet10, ET::Hex8, ET::Hex20, ET::Hex27}, p.radius, p.grading);
  const bool block =
      requireBase("half-sphere", p.base, {"none", "block"}, p.baseWidth, p.baseHeight);
  const std::string source = "generated half-sphere" + std::string(block ? " on a block" : "") +
                             " (" + p.elementType + ", R = " + numberText(p.radius) + ", sizes " +
                             numberText(p.grading.sizeContact) + " to " +
                             numberText(p.grading.sizeFar) + ")";
  return inGmshModel("gmsh could not generate the " + source, [&] {
    namespace occ = gmsh::model::occ;
    resetMeshOptions();
    const double cx = p.centre[0], cy = p.centre[1], cz = p.centre[2], r = p.radius;
    // OCC spheres have poles on their z axis and a seam at longitude 0. The half of the
    // sphere with y >= 0 (longitudes 0..pi) has both on its flat face; turning it by -90
    // degrees about x puts that face on z = 0 and the apex (0, R, 0), a regular point of the
    // surface, at the contact point (0, 0, -R).
    const int volume = occ::addSphere(0, 0, 0, r, -1, -M_PI / 2, M_PI / 2, M_PI);
    occ::rotate({{3, volume}}, 0, 0, 0, 1, 0, 0, -M_PI / 2);
    occ::translate({{3, volume}}, cx, cy, cz);
    const int contact = occ::addPoint(cx, cy, cz - r);
    // Not fragmented with the sphere: the two bodies are meshed separately (disjoint nodes).
    const int base =
        block ? occ::addBox(cx - p.baseWidth / 2, cy - p.baseWidth / 2, cz - r - p.baseHeight,
                            p.baseWidth, p.baseWidth, p.baseHeight)
              : -1;
    occ::synchronize();
    gmsh::vectorpair faces;
    gmsh::model::getBoundary({{3, volume}}, faces, false, false, false);
    // Bounding boxes of curved OCC faces are loose: classify by centre of mass instead.
    std::vector<int> flat, curved;
    for (const auto& f : faces) {
      const int tag = std::abs(f.second);
      (std::abs(centerOfMass(2, tag)[2] - cz) < 1e-8 * r ? flat : curved).push_back(tag);
    }
    gmsh::model::mesh::embed(0, {contact}, 2, curved.at(0));
    addGroup(3, {volume}, "body");
    addGroup(2, flat, "flat");
    addGroup(2, curved, "curved");
    addGroup(0, {contact}, "contact-point");
    if (block) {
      gmsh::model::getBoundary({{3, base}}, faces, false, false, false);
      std::vector<int> top, bottom, sides;
      for (const auto& f : faces) {
        const int tag = std::abs(f.second);
        const double z = centerOfMass(2, tag)[2];
        (std::abs(z - (cz - r)) < 1e-8 * r                  ? top
         : std::abs(z - (cz - r - p.baseHeight)) < 1e-8 * r ? bottom
                                                            : sides)
            .push_back(tag);
      }
      addGroup(3, {base}, "base");
      addGroup(2, top, "base-top");
      addGroup(2, bottom, "base-bottom");
      addGroup(2, sides, "base-sides");
    }
    // Hexes: every tet is split into 4 hexes, which halves the edges; mesh twice as coarse.
    if (!spec.simplex) gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 2);
    generateGraded(3, {cx, cy, cz - r}, p.grading, spec.simplex ? 1.0 : 2.0);
    applyOrder(spec);
    return meshFromGmshModel(source, source);
  });
}

}  // namespace contactlab
