#pragma once
// Internal to core/mesh: the outline of the blade-root generator's two bodies as straight-edged
// polygons with the corners to round (no gmsh here, so the element estimate and the tests can
// use it too). Geometry and parameters: BladeRootParams in MeshGenerators.hpp.
#include "core/mesh/MeshGenerators.hpp"

#include <array>
#include <vector>

namespace contactlab {

class BladeRootProfile {
 public:
  using Point = std::array<double, 2>;
  enum class EdgeKind { Flank, Free, Top };

  // Throws std::invalid_argument naming the parameter when the outline would be degenerate:
  // a lower flank that does not descend, a neck of no width, a slot outside the sector or
  // through its inner radius, a fillet that does not fit on its edges, crossing edges.
  explicit BladeRootProfile(const BladeRootParams& p);

  // The blade's closed outline, counter-clockwise; edge i runs from blade()[i] to
  // blade()[i + 1] (the last one back to the first) and is of kind bladeEdges()[i].
  const std::vector<Point>& blade() const { return blade_; }
  const std::vector<EdgeKind>& bladeEdges() const { return bladeEdges_; }
  // Fillet radius at each vertex (0: sharp).
  const std::vector<double>& bladeFillets() const { return bladeFillets_; }

  // The slot's open outline in the disc's counter-clockwise order: from the mouth on the right
  // (on the outer circle) down around the bottom up to the mouth on the left; edge i runs from
  // slot()[i] to slot()[i + 1]. Flank edges coincide with the blade's; Free ones stand
  // Clearance off the blade.
  const std::vector<Point>& slot() const { return slot_; }
  const std::vector<EdgeKind>& slotEdges() const { return slotEdges_; }
  const std::vector<double>& slotFillets() const { return slotFillets_; }

  // The contact flanks as segments (the blade's, which are also the disc's), for size fields.
  const std::vector<std::array<Point, 2>>& flanks() const { return flanks_; }
  // Distance from (x, y) to the nearest contact flank.
  double flankDistance(double x, double y) const;

 private:
  std::vector<Point> blade_, slot_;
  std::vector<EdgeKind> bladeEdges_, slotEdges_;
  std::vector<double> bladeFillets_, slotFillets_;
  std::vector<std::array<Point, 2>> flanks_;
};

// How far a fillet of `radius` at vertex b (edges a -> b -> c) reaches along each edge.
double filletTangentLength(const BladeRootProfile::Point& a, const BladeRootProfile::Point& b,
                           const BladeRootProfile::Point& c, double radius);

}  // namespace contactlab
