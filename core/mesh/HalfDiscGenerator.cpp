#include "core/mesh/GeneratorSupport.hpp"
#include "core/mesh/GmshExtract.hpp"
#include "core/mesh/GmshModel.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <gmsh.h>

namespace contactlab {
Mesh generateHalfDisc(const HalfDiscParams& p) {
  using ET = ElementType;
  const auto spec =
      roundBodySpec("half-disc", p.elementType,
                    {ET::Tri3, ET::Tri6, ET::Quad4, ET::Quad8, ET::Quad9}, p.radius, p.grading);
  const std::string source =
      "generated half-disc (" + p.elementType + ", R = " + numberText(p.radius) + ", sizes " +
      numberText(p.grading.sizeContact) + " to " + numberText(p.grading.sizeFar) + ")";
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

Mesh generateRollerOnBase(const RollerOnBaseParams& p) {
  using ET = ElementType;
  const auto spec =
      roundBodySpec("roller-on-base", p.elementType,
                    {ET::Tri3, ET::Tri6, ET::Quad4, ET::Quad8, ET::Quad9}, p.radius, p.grading);
  const bool disc =
      !requireBase("roller-on-base", p.base, {"block", "disc"}, p.baseWidth, p.baseHeight);
  const std::string source = "generated roller on a " + p.base + " (" + p.elementType +
                             ", R = " + numberText(p.radius) + ")";
  return inGmshModel("gmsh could not generate the " + source, [&] {
    namespace occ = gmsh::model::occ;
    resetMeshOptions();
    const double x0 = p.contact[0], y0 = p.contact[1], r = p.radius;
    // A half disc with its arc towards the contact point, counter-clockwise (normal +z); the
    // contact point is a geometric vertex of each body (two vertices, two nodes).
    struct HalfDisc {
      int surface, flat, arcA, arcB;
    };
    auto halfDisc = [&](double side) {  // side = +1: above the contact point, -1: below
      const double cy = y0 + side * r;
      const int centre = occ::addPoint(x0, cy, 0);
      const int contact = occ::addPoint(x0, y0, 0);
      const int a = occ::addPoint(x0 + side * r, cy, 0);
      const int b = occ::addPoint(x0 - side * r, cy, 0);
      HalfDisc h;
      h.arcA = occ::addCircleArc(contact, centre, a);
      h.flat = occ::addLine(a, b);
      h.arcB = occ::addCircleArc(b, centre, contact);
      h.surface = occ::addPlaneSurface({occ::addCurveLoop({h.arcA, h.flat, h.arcB})});
      occ::remove({{0, centre}});
      return h;
    };
    const HalfDisc roller = halfDisc(+1);
    std::vector<int> baseSurface, baseTop, baseBottom, baseLeft, baseRight;
    if (disc) {
      const HalfDisc base = halfDisc(-1);
      baseSurface = {base.surface};
      baseTop = {base.arcA, base.arcB};
      baseBottom = {base.flat};
    } else {
      const double w = p.baseWidth, h = p.baseHeight;
      const int bl = occ::addPoint(x0 - w / 2, y0 - h, 0);
      const int br = occ::addPoint(x0 + w / 2, y0 - h, 0);
      const int tr = occ::addPoint(x0 + w / 2, y0, 0);
      const int top = occ::addPoint(x0, y0, 0);
      const int tl = occ::addPoint(x0 - w / 2, y0, 0);
      const int bottom = occ::addLine(bl, br), right = occ::addLine(br, tr);
      const int topRight = occ::addLine(tr, top), topLeft = occ::addLine(top, tl);
      const int left = occ::addLine(tl, bl);
      baseSurface = {
          occ::addPlaneSurface({occ::addCurveLoop({bottom, right, topRight, topLeft, left})})};
      baseTop = {topRight, topLeft};
      baseBottom = {bottom};
      baseLeft = {left};
      baseRight = {right};
    }
    occ::synchronize();
    addGroup(2, {roller.surface}, "roller");
    addGroup(2, baseSurface, "base");
    addGroup(1, {roller.flat}, "roller-flat");
    addGroup(1, {roller.arcA, roller.arcB}, "roller-curved");
    addGroup(1, baseTop, "base-top");
    addGroup(1, baseBottom, "base-bottom");
    if (!disc) {
      addGroup(1, baseLeft, "base-left");
      addGroup(1, baseRight, "base-right");
    }
    if (!spec.simplex) {
      gmsh::option::setNumber("Mesh.RecombineAll", 1);
      gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 3);  // blossom full-quad
    }
    generateGraded(2, {x0, y0, 0}, p.grading, 1.0);
    if (!spec.simplex) requireAllQuads(source);
    applyOrder(spec);
    return meshFromGmshModel(source, source);
  });
}

}  // namespace contactlab
