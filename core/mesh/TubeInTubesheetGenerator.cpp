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

constexpr const char* kName = "tube-in-tubesheet";

void fail(const std::string& message) {
  throw std::invalid_argument(std::string(kName) + " generator: " + message);
}

void requireTube(const TubeInTubesheetParams& p) {
  requirePositive(kName, "Tube Outer Diameter", p.tubeOuterDiameter);
  requirePositive(kName, "Tube Wall", p.tubeWall);
  requirePositive(kName, "Thickness", p.thickness);
  requirePositive(kName, "Sheet Radial Grading", p.sheetRadialGrading);
  if (!(p.tubeWall < p.tubeOuterDiameter / 2))
    fail("Tube Wall = " + numberText(p.tubeWall) + " must be less than the outer radius " +
         numberText(p.tubeOuterDiameter / 2));
  if (!(p.clearance >= 0)) fail("Clearance = " + numberText(p.clearance) + " must be >= 0");
  const double hole = p.tubeOuterDiameter / 2 + p.clearance;
  if (!(p.sheetOuterRadius > hole))
    fail("Sheet Outer Radius = " + numberText(p.sheetOuterRadius) +
         " must be larger than the hole's radius " + numberText(hole));
  if (!(p.expansionStart >= 0 && p.expansionStart < p.expansionEnd &&
        p.expansionEnd <= p.thickness))
    fail("the expansion zone [Expansion Start, Expansion End] = [" + numberText(p.expansionStart) +
         ", " + numberText(p.expansionEnd) +
         "] must be a non-empty part of [0, Thickness = " + numberText(p.thickness) + "]");
  if (!(p.angle > 0 && p.angle <= 90))
    fail("Angle = " + numberText(p.angle) + " must lie in (0, 90] degrees");
  requireDivisions(kName, "Tube Radial Divisions", p.tubeRadialDivisions);
  requireDivisions(kName, "Sheet Radial Divisions", p.sheetRadialDivisions);
  requireDivisions(kName, "Circumferential Divisions", p.circumferentialDivisions);
  requireDivisions(kName, "Axial Divisions (along the expansion)", p.axialDivisions[1]);
  if (p.sheetCircumferentialDivisions < 0 || p.sheetAxialDivisions < 0)
    fail(
        "Sheet Circumferential Divisions and Sheet Axial Divisions must be >= 0 (0: the "
        "tube's)");
  const double lengths[3] = {p.expansionStart, p.expansionEnd - p.expansionStart,
                             p.thickness - p.expansionEnd};
  const char* parts[3] = {"below", "along", "above"};
  for (int i : {0, 2})
    if ((lengths[i] > 0) != (p.axialDivisions[i] > 0))
      fail(std::string("Axial Divisions ") + parts[i] + " the expansion zone = " +
           std::to_string(p.axialDivisions[i]) + (lengths[i] > 0 ? " must be >= 1" : " must be 0") +
           " for a length of " + numberText(lengths[i]));
}

// Grid z (integers at grid planes, halves at mid-side nodes) to z: linear in each zone.
double axialPosition(double k, const TubeInTubesheetParams& p) {
  const double bounds[4] = {0, p.expansionStart, p.expansionEnd, p.thickness};
  double start = 0;
  for (int zone = 0; zone < 3; ++zone) {
    const int n = p.axialDivisions[zone];
    if (k <= start + n || zone == 2)
      return n == 0 ? bounds[zone + 1]
                    : bounds[zone] + (k - start) / n * (bounds[zone + 1] - bounds[zone]);
    start += n;
  }
  return p.thickness;
}

// A body's radius at grid x = s (its radii at integers, linear between).
double radiusAt(double s, const std::vector<double>& radii) {
  const int n = static_cast<int>(radii.size()) - 1;
  const int i = std::clamp(static_cast<int>(std::floor(s)), 0, n - 1);
  return radii[i] + (s - i) * (radii[i + 1] - radii[i]);
}

}  // namespace

Mesh generateTubeInTubesheet(const TubeInTubesheetParams& p) {
  using ET = ElementType;
  const auto spec = elementSpec(kName, p.elementType, {ET::Hex8, ET::Hex20, ET::Hex27});
  requireTube(p);
  const int nrT = p.tubeRadialDivisions, nrS = p.sheetRadialDivisions;
  const int nt = p.circumferentialDivisions;
  const int nz = p.axialDivisions[0] + p.axialDivisions[1] + p.axialDivisions[2];
  const int ntS = p.sheetCircumferentialDivisions > 0 ? p.sheetCircumferentialDivisions : nt;
  const int nzS = p.sheetAxialDivisions > 0 ? p.sheetAxialDivisions : nz;
  const std::string source = "generated tube in tubesheet (" + p.elementType + ", " +
                             std::to_string(nrT * nt * nz + nrS * ntS * nzS) + " cells)";
  // Both bodies as structured boxes in grid space (x: radial index, y: circumferential, z:
  // axial), the tubesheet's one grid unit beyond the tube's, then mapped: grid planes become
  // the cylinders, the radial half-planes and the z planes, and mid-side nodes land on them.
  const double sheetStart = nrT + 1.0;
  Mesh mesh = inGmshModel("gmsh could not generate the " + source, [&] {
    resetMeshOptions();
    const auto tube =
        addStructuredBox({0, 0, 0}, {double(nrT), double(nt), double(nz)}, {nrT, nt, nz}, true);
    const auto sheet = addStructuredBox({sheetStart, 0, 0}, {double(nrS), double(ntS), double(nzS)},
                                        {nrS, ntS, nzS}, true);
    addGroup(3, {tube.volume}, "tube");
    addGroup(3, {sheet.volume}, "tubesheet");
    // Faces: xmin, xmax, ymin, ymax, zmin, zmax.
    addGroup(2, {tube.faces[0]}, "tube-inner");
    addGroup(2, {tube.faces[1]}, "tube-outer");
    addGroup(2, {sheet.faces[0]}, "hole");
    addGroup(2, {sheet.faces[1]}, "sheet-outer");
    addGroup(2, {tube.faces[4]}, "tube-bottom");
    addGroup(2, {tube.faces[5]}, "tube-top");
    addGroup(2, {sheet.faces[4]}, "sheet-bottom");
    addGroup(2, {sheet.faces[5]}, "sheet-top");
    addGroup(2, {tube.faces[2], sheet.faces[2]}, "cut-start");
    addGroup(2, {tube.faces[3], sheet.faces[3]}, "cut-end");
    gmsh::model::mesh::generate(3);
    applyOrder(spec);
    return meshFromGmshModel(source, source);
  });

  const double outer = p.tubeOuterDiameter / 2;
  std::vector<double> tubeRadii(nrT + 1);
  for (int i = 0; i <= nrT; ++i)
    tubeRadii[i] = outer - p.tubeWall + p.tubeWall * i / nrT;
  const auto sheetRadii =
      ringSectorRadii(outer + p.clearance, p.sheetOuterRadius, nrS, p.sheetRadialGrading);
  const double angle = p.angle * M_PI / 180.0;
  for (std::size_t n = 0; n < mesh.numNodes(); ++n) {
    double* x = &mesh.coords[3 * n];
    // Every node of a structured order-1 or order-2 grid sits at a multiple of 1/2.
    const double s = std::round(2 * x[0]) / 2, t = std::round(2 * x[1]) / 2;
    const double k = std::round(2 * x[2]) / 2;
    const bool inTube = s < sheetStart - 0.25;
    const double r = inTube ? radiusAt(s, tubeRadii) : radiusAt(s - sheetStart, sheetRadii);
    // The start cut is exactly y = 0 (a plane normal to an axis: a Dirichlet condition).
    const double theta = t / (inTube ? nt : ntS) * angle;
    x[0] = t == 0 ? r : r * std::cos(theta);
    x[1] = t == 0 ? 0.0 : r * std::sin(theta);
    x[2] = inTube ? axialPosition(k, p) : k / nzS * p.thickness;
  }

  // The expansion zone's part of the tube's inner face: its facets between the zone's planes.
  std::vector<CellGroup> expanded;
  const double tol = 1e-9 * p.thickness;
  for (const CellGroup& g : mesh.boundaries) {
    if (g.name != "tube-inner") continue;
    CellGroup part{"tube-inner-expanded", g.dim, g.type, {}, {}};
    const int npc = g.nodesPerCell();
    for (std::size_t c = 0; c < g.size(); ++c) {
      bool inside = true;
      for (int a = 0; a < npc; ++a) {
        const double z = mesh.coords[3 * g.nodes[c * npc + a] + 2];
        inside = inside && z >= p.expansionStart - tol && z <= p.expansionEnd + tol;
      }
      if (!inside) continue;
      part.nodes.insert(part.nodes.end(), g.nodes.begin() + c * npc,
                        g.nodes.begin() + (c + 1) * npc);
      part.tags.push_back(g.tags[c]);
    }
    expanded.push_back(std::move(part));
  }
  mesh.boundaries.insert(mesh.boundaries.end(), expanded.begin(), expanded.end());
  return mesh;
}

}  // namespace contactlab
