#include "core/mesh/ElementEstimate.hpp"

#include "core/mesh/BladeRootProfile.hpp"
#include "core/mesh/ElementType.hpp"
#include "core/mesh/GeneratorSupport.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <stdexcept>

namespace contactlab {
namespace {

// Triangles and tetrahedra, by the element's own type (a name the generator has not checked
// yet counts as not simplex: the generator refuses it with its own sentence).
bool simplex(const std::string& name) {
  try {
    const ElementType type = elementTypeFromName(name);
    return type == ElementType::Tri3 || type == ElementType::Tri6 || type == ElementType::Tet4 ||
           type == ElementType::Tet10;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

// Hexahedra of a structured box of n[0] x n[1] x n[2] divisions.
double boxCells(const std::array<int, 3>& n) {
  return double(n[0]) * n[1] * n[2];
}

// Cells of a structured block: quads/hexes, or 2 triangles / 6 tetrahedra each.
double structured(const std::string& type, double cells, int dim) {
  return simplex(type) ? cells * (dim == 2 ? 2 : 6) : cells;
}

// Elements per h^dim for a graded (unstructured) mesh of that element type.
double perCell(const std::string& type, int dim) {
  if (dim == 2) return simplex(type) ? 2.3 : 1.2;
  return simplex(type) ? 6.0 : 24.0;  // hexes: each tetrahedron split into 4
}

double size(const ContactGrading& g, double d) {
  if (d <= g.fineRadius) return g.sizeContact;
  const double t = std::min(1.0, (d - g.fineRadius) / g.transitionLength);
  return g.sizeContact + t * (g.sizeFar - g.sizeContact);
}

// The integral of perCell / h(d)^dim over the region `inside` of the box [lo, hi], d the distance
// to `contact`, by a midpoint rule on a grid (bounded integrand: h >= Size Contact).
double graded(int dim, const double* lo, const double* hi, const double* contact,
              const std::function<bool(const double*)>& inside, const ContactGrading& g,
              double elementsPerCell) {
  // Invalid sizes are the generator's to refuse, with its own sentence.
  const auto positive = [](double v) { return v > 0 && std::isfinite(v); };
  if (!positive(g.sizeContact) || !positive(g.sizeFar) || !positive(g.transitionLength) ||
      !(g.fineRadius >= 0) || !std::isfinite(g.fineRadius))
    return 0;
  for (int i = 0; i < dim; ++i)
    if (!(hi[i] > lo[i]) || !std::isfinite(hi[i] - lo[i])) return 0;
  const int n = dim == 2 ? 400 : 80;
  double step[3] = {1, 1, 1}, cell = 1;
  for (int i = 0; i < dim; ++i) {
    step[i] = (hi[i] - lo[i]) / n;
    cell *= step[i];
  }
  // Near the contact point the size may be far below the grid step: there the body is a half
  // plane / half space around the point (it touches there), integrated radially on a fine
  // logarithmic rule; the grid takes the rest.
  const double near = 3 * *std::max_element(step, step + dim);
  const double halfShell = dim == 2 ? M_PI : 2 * M_PI;  // measure of d = 1 in the half space
  double total = 0;
  const int radial = 4000;
  const double dmin = std::min(near, 1e-3 * g.sizeContact);
  for (int k = 0; k < radial; ++k) {
    const double d0 = dmin * std::pow(near / dmin, double(k) / radial);
    const double d1 = dmin * std::pow(near / dmin, double(k + 1) / radial);
    const double d = 0.5 * (d0 + d1);
    total += halfShell * std::pow(d, dim - 1) * (d1 - d0) / std::pow(size(g, d), dim);
  }
  if (dmin < near) total += halfShell * std::pow(dmin, dim) / dim / std::pow(g.sizeContact, dim);
  double x[3] = {0, 0, 0};
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int c = 0; c < (dim == 3 ? n : 1); ++c) {
        const int index[3] = {a, b, c};
        double d2 = 0;
        for (int i = 0; i < dim; ++i) {
          x[i] = lo[i] + (index[i] + 0.5) * step[i];
          d2 += (x[i] - contact[i]) * (x[i] - contact[i]);
        }
        if (d2 >= near * near && inside(x)) total += cell / std::pow(size(g, std::sqrt(d2)), dim);
      }
  return elementsPerCell * total;
}

// Lower half disc of radius r whose lowest point is `bottom`, and its mirror (upper half).
double halfDisc(const double* bottom, double r, bool lower, const ContactGrading& g,
                double elementsPerCell) {
  const double cy = lower ? bottom[1] + r : bottom[1] - r;
  const double lo[2] = {bottom[0] - r, lower ? bottom[1] : cy};
  const double hi[2] = {bottom[0] + r, lower ? cy : bottom[1]};
  return graded(
      2, lo, hi, bottom,
      [&](const double* x) {
        return (x[0] - bottom[0]) * (x[0] - bottom[0]) + (x[1] - cy) * (x[1] - cy) <= r * r;
      },
      g, elementsPerCell);
}

}  // namespace

double estimateElements(const RectangleParams& p) {
  return structured(p.elementType, double(p.divisions[0]) * p.divisions[1], 2);
}

double estimateElements(const RingSectorParams& p) {
  return structured(p.elementType, double(p.radialDivisions) * p.circumferentialDivisions, 2);
}

double estimateElements(const TubeInTubesheetParams& p) {
  const int nz = p.axialDivisions[0] + p.axialDivisions[1] + p.axialDivisions[2];
  const int ntS = p.sheetCircumferentialDivisions > 0 ? p.sheetCircumferentialDivisions
                                                      : p.circumferentialDivisions;
  const int nzS = p.sheetAxialDivisions > 0 ? p.sheetAxialDivisions : nz;
  return structured(p.elementType,
                    double(p.tubeRadialDivisions) * p.circumferentialDivisions * nz +
                        double(p.sheetRadialDivisions) * ntS * nzS,
                    3);
}

double estimateElements(const BoxParams& p) {
  return structured(p.elementType, double(p.divisions[0]) * p.divisions[1] * p.divisions[2], 3);
}

double estimateElements(const StackedBlocks2DParams& p) {
  return structured(p.elementType,
                    double(p.lowerDivisions[0]) * p.lowerDivisions[1] +
                        double(p.upperDivisions[0]) * p.upperDivisions[1],
                    2);
}

double estimateElements(const StackedBlocks3DParams& p) {
  return structured(p.elementType, boxCells(p.lowerDivisions) + boxCells(p.upperDivisions), 3);
}

double estimateElements(const DieOnSlabParams& p) {
  return structured(p.elementType, boxCells(p.slabDivisions) + boxCells(p.dieDivisions), 3);
}

double estimateElements(const HalfDiscParams& p) {
  const double bottom[2] = {p.centre[0], p.centre[1] - p.radius};
  return halfDisc(bottom, p.radius, true, p.grading, perCell(p.elementType, 2));
}

double estimateElements(const RollerOnBaseParams& p) {
  const double k = perCell(p.elementType, 2);
  const double roller = halfDisc(p.contact.data(), p.radius, true, p.grading, k);
  if (p.base == "disc") return roller + halfDisc(p.contact.data(), p.radius, false, p.grading, k);
  const double lo[2] = {p.contact[0] - 0.5 * p.baseWidth, p.contact[1] - p.baseHeight};
  const double hi[2] = {p.contact[0] + 0.5 * p.baseWidth, p.contact[1]};
  return roller +
         graded(
             2, lo, hi, p.contact.data(), [](const double*) { return true; }, p.grading, k);
}

double estimateElements(const BladeRootParams& p) {
  // Invalid parameters are the generator's to refuse, with its own sentence.
  std::unique_ptr<BladeRootProfile> profile;
  try {
    profile = std::make_unique<BladeRootProfile>(p);
    requireGrading("blade-root", {p.sizeFlank, p.sizeFar, p.fineDistance, p.transitionLength});
  } catch (const std::invalid_argument&) {
    return 0;
  }
  // The sector with the blade's shank on top (the slot's clearance is not worth resolving), on
  // a grid fine enough for the flank size: the area between the flanks is what counts.
  const double half = 0.5 * p.sectorAngle * M_PI / 180, top = p.outerRadius + p.bladeHeight;
  const double xmax = p.outerRadius * std::sin(half);
  const double ymin = p.innerRadius * std::cos(half);
  const int n = 800;
  const double dx = 2 * xmax / n, dy = (top - ymin) / n;
  const double neck = 0.5 * p.neckWidth;
  double total = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = -xmax + (i + 0.5) * dx, y = ymin + (j + 0.5) * dy;
      const double r = std::hypot(x, y);
      const bool inSector =
          r >= p.innerRadius && r <= p.outerRadius && std::abs(std::atan2(x, y)) <= half;
      const bool inShank = r > p.outerRadius && y <= top && std::abs(x) <= neck;
      if (!inSector && !inShank) continue;
      const double d = profile->flankDistance(x, y);
      const double t = std::clamp((d - p.fineDistance) / p.transitionLength, 0.0, 1.0);
      const double h = p.sizeFlank + t * (p.sizeFar - p.sizeFlank);
      total += dx * dy / (h * h);
    }
  // Swept (hex): the quads of the section times the layers.
  const bool swept = p.elementType.rfind("hex", 0) == 0;
  return (swept ? perCell("quad4", 2) * std::max(p.layers, 1) : perCell(p.elementType, 2)) * total;
}

double estimateElements(const HalfSphereParams& p) {
  const double k = perCell(p.elementType, 3), r = p.radius;
  const double bottom[3] = {p.centre[0], p.centre[1], p.centre[2] - r};
  const double lo[3] = {p.centre[0] - r, p.centre[1] - r, p.centre[2] - r};
  const double hi[3] = {p.centre[0] + r, p.centre[1] + r, p.centre[2]};
  double total = graded(
      3, lo, hi, bottom,
      [&](const double* x) {
        double d2 = 0;
        for (int i = 0; i < 3; ++i)
          d2 += (x[i] - p.centre[i]) * (x[i] - p.centre[i]);
        return d2 <= r * r;
      },
      p.grading, k);
  if (p.base == "block") {
    const double w = 0.5 * p.baseWidth;
    const double blo[3] = {bottom[0] - w, bottom[1] - w, bottom[2] - p.baseHeight};
    const double bhi[3] = {bottom[0] + w, bottom[1] + w, bottom[2]};
    total += graded(
        3, blo, bhi, bottom, [](const double*) { return true; }, p.grading, k);
  }
  return total;
}

void requireElementLimit(const std::string& generator, double estimate, int limit) {
  if (limit < 1)
    throw std::invalid_argument(generator + " generator: " + kMaxElementsKey + " = " +
                                std::to_string(limit) + " must be at least 1");
  if (!(estimate <= limit)) {  // NaN too
    char text[64];
    std::snprintf(text, sizeof text, "%.3g", estimate);
    throw std::invalid_argument(generator + " generator: these sizes would make about " + text +
                                " elements, more than " + kMaxElementsKey + " = " +
                                std::to_string(limit) + "; coarsen the mesh, or raise " +
                                kMaxElementsKey + " if this machine has the memory for it");
  }
}

}  // namespace contactlab
