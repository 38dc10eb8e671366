#include "core/mesh/BladeRootProfile.hpp"
#include "core/mesh/GeneratorSupport.hpp"
#include "core/mesh/GmshExtract.hpp"
#include "core/mesh/GmshModel.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>

namespace contactlab {
namespace {

using Point = BladeRootProfile::Point;
using EdgeKind = BladeRootProfile::EdgeKind;

// The OCC curves of an outline whose corners are rounded: the straight piece of each edge (by
// the edge's index), the fillet arc at each vertex (0: a sharp vertex), and all of them in order
// for a curve loop.
struct RoundedOutline {
  std::vector<int> edgeLines;
  std::vector<int> arcAt;
  std::vector<int> loop;
  int firstPoint = 0, lastPoint = 0;  // open outlines: the OCC points at the ends
};

RoundedOutline addRoundedOutline(const std::vector<Point>& v, const std::vector<double>& fillets,
                                 bool closed) {
  namespace occ = gmsh::model::occ;
  const std::size_t n = v.size();
  // Each vertex becomes the point where the straight piece before it ends and the one where the
  // piece after it starts (one point when sharp), joined by the fillet's arc.
  std::vector<int> endIn(n), startOut(n), arcAt(n, 0), centres;
  for (std::size_t i = 0; i < n; ++i) {
    const bool interior = closed || (i > 0 && i + 1 < n);
    if (!interior || fillets[i] <= 0) {
      endIn[i] = startOut[i] = occ::addPoint(v[i][0], v[i][1], 0);
      continue;
    }
    const Point& a = v[(i + n - 1) % n];
    const Point& c = v[(i + 1) % n];
    const double t = filletTangentLength(a, v[i], c, fillets[i]);
    const double l1 = std::hypot(v[i][0] - a[0], v[i][1] - a[1]);
    const double l2 = std::hypot(c[0] - v[i][0], c[1] - v[i][1]);
    const Point d1{(v[i][0] - a[0]) / l1, (v[i][1] - a[1]) / l1};
    const Point d2{(c[0] - v[i][0]) / l2, (c[1] - v[i][1]) / l2};
    const Point t1{v[i][0] - t * d1[0], v[i][1] - t * d1[1]};
    const Point t2{v[i][0] + t * d2[0], v[i][1] + t * d2[1]};
    // The centre lies on the inside of the turn, a radius off the incoming edge.
    const double side = d1[0] * d2[1] - d1[1] * d2[0] > 0 ? 1.0 : -1.0;
    const Point centre{t1[0] - side * fillets[i] * d1[1], t1[1] + side * fillets[i] * d1[0]};
    endIn[i] = occ::addPoint(t1[0], t1[1], 0);
    startOut[i] = occ::addPoint(t2[0], t2[1], 0);
    centres.push_back(occ::addPoint(centre[0], centre[1], 0));
    arcAt[i] = occ::addCircleArc(endIn[i], centres.back(), startOut[i]);
  }
  RoundedOutline out;
  const std::size_t edges = closed ? n : n - 1;
  for (std::size_t i = 0; i < edges; ++i) {
    if (arcAt[i]) out.loop.push_back(arcAt[i]);
    out.edgeLines.push_back(occ::addLine(startOut[i], endIn[(i + 1) % n]));
    out.loop.push_back(out.edgeLines.back());
  }
  for (int c : centres)
    occ::remove({{0, c}});
  out.arcAt = arcAt;
  out.firstPoint = endIn.front();
  out.lastPoint = startOut.back();
  return out;
}

std::vector<int> linesOf(const RoundedOutline& o, const std::vector<EdgeKind>& kinds,
                         EdgeKind kind) {
  std::vector<int> lines;
  for (std::size_t i = 0; i < kinds.size(); ++i)
    if (kinds[i] == kind) lines.push_back(o.edgeLines[i]);
  return lines;
}

// The contact flanks with the fillets at their ends: a flank's contact runs on into the
// rounded lobe tip under load, and cutting the contact group at the tangent point would make
// an artificial edge of contact there (a pressure peak that grows without bound with mesh
// refinement).
std::vector<int> flankCurves(const RoundedOutline& o, const std::vector<EdgeKind>& kinds) {
  std::vector<int> curves = linesOf(o, kinds, EdgeKind::Flank);
  const std::size_t n = o.arcAt.size();
  for (std::size_t i = 0; i < kinds.size(); ++i)
    if (kinds[i] == EdgeKind::Flank)
      for (std::size_t v : {i, (i + 1) % n})
        if (o.arcAt[v]) curves.push_back(o.arcAt[v]);
  return curves;
}

// The other faces: lines that are not flanks or the top, arcs that do not end a flank.
std::vector<int> freeCurves(const RoundedOutline& o, const std::vector<EdgeKind>& kinds) {
  std::vector<int> curves = linesOf(o, kinds, EdgeKind::Free);
  const auto flanks = flankCurves(o, kinds);
  for (int arc : o.arcAt)
    if (arc && std::find(flanks.begin(), flanks.end(), arc) == flanks.end()) curves.push_back(arc);
  return curves;
}

}  // namespace

Mesh generateBladeRoot(const BladeRootParams& p) {
  using ET = ElementType;
  const auto spec = elementSpec("blade-root", p.elementType,
                                {ET::Tri3, ET::Tri6, ET::Quad4, ET::Quad8, ET::Quad9});
  requireGrading("blade-root", {p.sizeFlank, p.sizeFar, p.fineDistance, p.transitionLength});
  const BladeRootProfile profile(p);
  const std::string source = "generated blade root (" + std::to_string(p.lobes) + " lobes, " +
                             p.elementType + ", flank size " + formatNumber(p.sizeFlank) + ")";
  return inGmshModel("gmsh could not generate the " + source, [&] {
    namespace occ = gmsh::model::occ;
    resetMeshOptions();
    const RoundedOutline blade = addRoundedOutline(profile.blade(), profile.bladeFillets(), true);
    const int bladeSurface = occ::addPlaneSurface({occ::addCurveLoop(blade.loop)});

    // The disc sector, counter-clockwise: up the right cut, along the outer arc to the slot's
    // mouth, around the slot, along the outer arc to the left cut, down it, back along the
    // inner arc.
    const RoundedOutline slot = addRoundedOutline(profile.slot(), profile.slotFillets(), false);
    const double h = 0.5 * p.sectorAngle * M_PI / 180, s = std::sin(h), c = std::cos(h);
    const int origin = occ::addPoint(0, 0, 0);
    const int innerRight = occ::addPoint(p.innerRadius * s, p.innerRadius * c, 0);
    const int outerRight = occ::addPoint(p.outerRadius * s, p.outerRadius * c, 0);
    const int outerLeft = occ::addPoint(-p.outerRadius * s, p.outerRadius * c, 0);
    const int innerLeft = occ::addPoint(-p.innerRadius * s, p.innerRadius * c, 0);
    const int sideRight = occ::addLine(innerRight, outerRight);
    const int outerArcRight = occ::addCircleArc(outerRight, origin, slot.firstPoint);
    const int outerArcLeft = occ::addCircleArc(slot.lastPoint, origin, outerLeft);
    const int sideLeft = occ::addLine(outerLeft, innerLeft);
    const int innerArc = occ::addCircleArc(innerLeft, origin, innerRight);
    std::vector<int> discLoop{sideRight, outerArcRight};
    discLoop.insert(discLoop.end(), slot.loop.begin(), slot.loop.end());
    discLoop.insert(discLoop.end(), {outerArcLeft, sideLeft, innerArc});
    const int discSurface = occ::addPlaneSurface({occ::addCurveLoop(discLoop)});
    occ::remove({{0, origin}});
    occ::synchronize();

    addGroup(2, {bladeSurface}, "blade");
    addGroup(2, {discSurface}, "disc");
    addGroup(1, flankCurves(blade, profile.bladeEdges()), "blade-flanks");
    addGroup(1, linesOf(blade, profile.bladeEdges(), EdgeKind::Top), "blade-top");
    addGroup(1, freeCurves(blade, profile.bladeEdges()), "blade-free");
    addGroup(1, flankCurves(slot, profile.slotEdges()), "disc-flanks");
    addGroup(1, freeCurves(slot, profile.slotEdges()), "disc-slot");
    addGroup(1, {innerArc}, "disc-inner");
    addGroup(1, {outerArcRight, outerArcLeft}, "disc-outer");
    addGroup(1, {sideRight, sideLeft}, "disc-sides");

    if (!spec.simplex) {
      gmsh::option::setNumber("Mesh.RecombineAll", 1);
      gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 3);  // blossom full-quad
    }
    generateWithSize(2, [&](double x, double y, double) {
      const double d = profile.flankDistance(x, y);
      const double t = std::clamp((d - p.fineDistance) / p.transitionLength, 0.0, 1.0);
      return p.sizeFlank + t * (p.sizeFar - p.sizeFlank);
    });
    if (!spec.simplex) requireAllQuads(source);
    applyOrder(spec);
    return meshFromGmshModel(source, source);
  });
}

}  // namespace contactlab
