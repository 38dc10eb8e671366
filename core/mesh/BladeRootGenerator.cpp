#include "core/mesh/BladeRootProfile.hpp"
#include "core/mesh/GeneratorSupport.hpp"
#include "core/mesh/GmshExtract.hpp"
#include "core/mesh/GmshModel.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

// The face of `volume` swept from the 2D curve `curve`: the one whose centre of mass lies over
// the curve's (the volume's own faces only, so that the coinciding flanks of blade and disc stay
// apart; the front and back faces are off by half the thickness in z).
int sweptFace(int volume, int curve, double thickness) {
  std::vector<std::pair<int, int>> faces;
  gmsh::model::getBoundary({{3, volume}}, faces, false, false, false);
  const auto c = centerOfMass(1, curve);
  const double tol = 1e-9 * (1 + std::abs(c[0]) + std::abs(c[1]));
  for (const auto& face : faces) {
    const auto f = centerOfMass(2, std::abs(face.second));
    if (std::abs(f[0] - c[0]) < tol && std::abs(f[1] - c[1]) < tol &&
        std::abs(f[2] - 0.5 * thickness) < 1e-9 * thickness)
      return std::abs(face.second);
  }
  throw std::logic_error("blade-root generator: no swept face for a curve of the outline");
}

// Names the group of dimension dim - 1 in 2D, or, extruded, the faces swept from its curves.
void addBoundaryGroup(int volume, double thickness, const std::vector<int>& curves,
                      const std::string& name) {
  if (volume == 0) return addGroup(1, curves, name);
  std::vector<int> faces;
  for (int c : curves)
    faces.push_back(sweptFace(volume, c, thickness));
  addGroup(2, faces, name);
}

}  // namespace

Mesh generateBladeRoot(const BladeRootParams& p) {
  using ET = ElementType;
  const auto spec = elementSpec(
      "blade-root", p.elementType,
      {ET::Tri3, ET::Tri6, ET::Quad4, ET::Quad8, ET::Quad9, ET::Hex8, ET::Hex20, ET::Hex27});
  const bool extruded = info(spec.type).dim == 3;
  if (extruded) {
    requirePositive("blade-root", "Thickness", p.thickness);
    requireDivisions("blade-root", "Layers", p.layers);
  }
  requireGrading("blade-root", {p.sizeFlank, p.sizeFar, p.fineDistance, p.transitionLength});
  const BladeRootProfile profile(p);
  const std::string source = "generated blade root (" + std::to_string(p.lobes) + " lobes, " +
                             p.elementType + ", flank size " + numberText(p.sizeFlank) + ")";
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
    // 3D: both sections swept along z in Layers structured layers (hexahedra from the quads).
    int bladeVolume = 0, discVolume = 0, bladeFront = 0, discFront = 0;
    if (extruded) {
      std::vector<std::pair<int, int>> swept;
      occ::extrude({{2, bladeSurface}, {2, discSurface}}, 0, 0, p.thickness, swept, {p.layers}, {},
                   true);
      // Per input surface: its copy at z = Thickness, then its volume, then the lateral faces.
      std::vector<int> volumes, fronts;
      for (std::size_t i = 1; i < swept.size(); ++i)
        if (swept[i].first == 3) {
          volumes.push_back(swept[i].second);
          fronts.push_back(swept[i - 1].second);
        }
      bladeVolume = volumes.at(0), discVolume = volumes.at(1);
      bladeFront = fronts.at(0), discFront = fronts.at(1);
    }
    occ::synchronize();

    const int cell = extruded ? 3 : 2;
    addGroup(cell, {extruded ? bladeVolume : bladeSurface}, "blade");
    addGroup(cell, {extruded ? discVolume : discSurface}, "disc");
    addBoundaryGroup(bladeVolume, p.thickness, flankCurves(blade, profile.bladeEdges()),
                     "blade-flanks");
    addBoundaryGroup(bladeVolume, p.thickness, linesOf(blade, profile.bladeEdges(), EdgeKind::Top),
                     "blade-top");
    addBoundaryGroup(bladeVolume, p.thickness, freeCurves(blade, profile.bladeEdges()),
                     "blade-free");
    addBoundaryGroup(discVolume, p.thickness, flankCurves(slot, profile.slotEdges()),
                     "disc-flanks");
    addBoundaryGroup(discVolume, p.thickness, freeCurves(slot, profile.slotEdges()), "disc-slot");
    addBoundaryGroup(discVolume, p.thickness, {innerArc}, "disc-inner");
    addBoundaryGroup(discVolume, p.thickness, {outerArcRight, outerArcLeft}, "disc-outer");
    addBoundaryGroup(discVolume, p.thickness, {sideRight, sideLeft}, "disc-sides");
    // Each radial cut alone, for a symmetry (roller) condition on its plane.
    addBoundaryGroup(discVolume, p.thickness, {sideRight}, "disc-side-right");
    addBoundaryGroup(discVolume, p.thickness, {sideLeft}, "disc-side-left");
    if (extruded) {
      addGroup(2, {bladeSurface}, "blade-back");
      addGroup(2, {bladeFront}, "blade-front");
      addGroup(2, {discSurface}, "disc-back");
      addGroup(2, {discFront}, "disc-front");
    }

    if (!spec.simplex) {
      gmsh::option::setNumber("Mesh.RecombineAll", 1);
      gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 3);  // blossom full-quad
    }
    generateWithSize(cell, [&](double x, double y, double) {
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
