#include "core/mesh/BladeRootProfile.hpp"

#include "core/mesh/GeneratorSupport.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace contactlab {
namespace {

using Point = BladeRootProfile::Point;
using EdgeKind = BladeRootProfile::EdgeKind;

constexpr const char* kGenerator = "blade-root generator: ";

[[noreturn]] void refuse(const std::string& what) {
  throw std::invalid_argument(kGenerator + what);
}

double cross(const Point& a, const Point& b) {
  return a[0] * b[1] - a[1] * b[0];
}

Point minus(const Point& a, const Point& b) {
  return {a[0] - b[0], a[1] - b[1]};
}

double length(const Point& a) {
  return std::hypot(a[0], a[1]);
}

// Intersection of the lines p1 + s d1 and p2 + t d2 (not parallel: consecutive outline edges).
Point intersect(const Point& p1, const Point& d1, const Point& p2, const Point& d2) {
  const double s = cross(minus(p2, p1), d2) / cross(d1, d2);
  return {p1[0] + s * d1[0], p1[1] + s * d1[1]};
}

// Proper crossing or touching of the segments ab and cd (collinear ones only when they
// overlap: the tip lands of a tapered root may lie on the line of the shank).
bool segmentsMeet(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double d1 = cross(minus(b, a), minus(c, a)), d2 = cross(minus(b, a), minus(d, a));
  const double d3 = cross(minus(d, c), minus(a, c)), d4 = cross(minus(d, c), minus(b, c));
  if (d1 == 0 && d2 == 0) {
    for (int i = 0; i < 2; ++i)
      if (std::max(a[i], b[i]) < std::min(c[i], d[i]) ||
          std::max(c[i], d[i]) < std::min(a[i], b[i]))
        return false;
    return true;
  }
  return ((d1 > 0) != (d2 > 0) || d1 == 0 || d2 == 0) &&
         ((d3 > 0) != (d4 > 0) || d3 == 0 || d4 == 0);
}

double segmentDistance(const Point& p, const Point& a, const Point& b) {
  const Point ab = minus(b, a), ap = minus(p, a);
  const double t =
      std::clamp((ap[0] * ab[0] + ap[1] * ab[1]) / (ab[0] * ab[0] + ab[1] * ab[1]), 0.0, 1.0);
  return std::hypot(ap[0] - t * ab[0], ap[1] - t * ab[1]);
}

// Every fillet must leave a straight piece of each edge, and edges that are not neighbours must
// not meet (an outline that crosses itself cannot be meshed).
void requireValidOutline(const std::string& body, const std::vector<Point>& v,
                         const std::vector<double>& fillets, bool closed) {
  const std::size_t n = v.size(), edges = closed ? n : n - 1;
  std::vector<double> reach(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (fillets[i] <= 0) continue;
    reach[i] = filletTangentLength(v[(i + n - 1) % n], v[i], v[(i + 1) % n], fillets[i]);
  }
  for (std::size_t i = 0; i < edges; ++i) {
    const std::size_t j = (i + 1) % n;
    if (!(reach[i] + reach[j] < length(minus(v[j], v[i]))))
      refuse("the " + body + "'s edge from (" + numberText(v[i][0]) + ", " + numberText(v[i][1]) +
             ") to (" + numberText(v[j][0]) + ", " + numberText(v[j][1]) +
             ") is too short for its fillets: reduce Fillet Radius or Clearance, or lengthen "
             "the lobes (Lobe Pitch, Lobe Depth, Tip Land, Neck Length)");
  }
  for (std::size_t i = 0; i < edges; ++i)
    for (std::size_t k = i + 2; k < edges; ++k) {
      if (closed && i == 0 && k == edges - 1) continue;  // neighbours through the last vertex
      if (segmentsMeet(v[i], v[(i + 1) % n], v[k], v[(k + 1) % n]))
        refuse("the " + body +
               "'s outline crosses itself: the lobes overlap (reduce Lobe Depth or Taper, or "
               "increase Lobe Pitch)");
    }
}

}  // namespace

double filletTangentLength(const Point& a, const Point& b, const Point& c, double radius) {
  const Point d1 = minus(b, a), d2 = minus(c, b);
  const double cosTurn =
      std::clamp((d1[0] * d2[0] + d1[1] * d2[1]) / (length(d1) * length(d2)), -1.0, 1.0);
  return radius * std::tan(0.5 * std::acos(cosTurn));
}

BladeRootProfile::BladeRootProfile(const BladeRootParams& p) {
  if (p.lobes < 1 || p.lobes > 4) refuse("Lobes = " + std::to_string(p.lobes) + " must be 1 to 4");
  const std::string g = "blade-root";
  requirePositive(g, "Inner Radius", p.innerRadius);
  requirePositive(g, "Outer Radius", p.outerRadius);
  if (!(p.outerRadius > p.innerRadius))
    refuse("Outer Radius = " + numberText(p.outerRadius) +
           " must exceed Inner Radius = " + numberText(p.innerRadius));
  if (!(p.sectorAngle > 0 && p.sectorAngle < 180))
    refuse("Sector Angle = " + numberText(p.sectorAngle) + " must lie in (0, 180) degrees");
  for (const auto& [name, value] : {std::pair<const char*, double>{"Neck Width", p.neckWidth},
                                    {"Neck Length", p.neckLength},
                                    {"Lobe Depth", p.lobeDepth},
                                    {"Lobe Pitch", p.lobePitch},
                                    {"Tip Land", p.tipLand},
                                    {"Clearance", p.clearance},
                                    {"Blade Height", p.bladeHeight}})
    requirePositive(g, name, value);
  if (!(p.taper >= 0) || !std::isfinite(p.taper))
    refuse("Taper = " + numberText(p.taper) + " must not be negative");
  if (!(p.filletRadius >= 0) || !std::isfinite(p.filletRadius))
    refuse("Fillet Radius = " + numberText(p.filletRadius) + " must not be negative");
  if (!(p.flankAngle > 0 && p.flankAngle < 75))
    refuse("Flank Angle = " + numberText(p.flankAngle) + " must lie in (0, 75) degrees");

  const int n = p.lobes;
  const double tanFlank = std::tan(p.flankAngle * M_PI / 180);
  const double drop = p.lobePitch - p.lobeDepth * tanFlank - p.tipLand;
  if (!(drop > 0))
    refuse("Lobe Pitch = " + numberText(p.lobePitch) +
           " leaves no lower flank: it must exceed Lobe Depth * tan(Flank Angle) + Tip Land = " +
           numberText(p.lobeDepth * tanFlank + p.tipLand));
  const double a0 = 0.5 * p.neckWidth;
  if (!(a0 - n * p.taper > 0))
    refuse("Taper = " + numberText(p.taper) + " leaves the lowest neck no width: Lobes * Taper " +
           "must stay below Neck Width / 2 = " + numberText(a0));

  // The right half, bottom to top: (point, kind of the edge to the next point).
  const double yFirst = p.outerRadius - p.neckLength;
  std::vector<Point> right;
  std::vector<EdgeKind> rightEdges;
  auto neck = [&](int k) { return Point{a0 - k * p.taper, yFirst - k * p.lobePitch}; };
  right.push_back(neck(n));
  rightEdges.push_back(EdgeKind::Free);
  for (int k = n - 1; k >= 0; --k) {
    const Point nk = neck(k);
    const double tipX = nk[0] + p.lobeDepth, tipTop = nk[1] - p.lobeDepth * tanFlank;
    right.push_back({tipX, tipTop - p.tipLand});
    rightEdges.push_back(EdgeKind::Free);
    right.push_back({tipX, tipTop});
    rightEdges.push_back(EdgeKind::Flank);
    flanks_.push_back({Point{tipX, tipTop}, nk});
    flanks_.push_back({Point{-tipX, tipTop}, Point{-nk[0], nk[1]}});
    right.push_back(nk);
    rightEdges.push_back(EdgeKind::Free);
  }
  right.push_back({a0, p.outerRadius + p.bladeHeight});
  rightEdges.push_back(EdgeKind::Top);

  // Counter-clockwise: up the right side, along the top, down the mirrored left side, back
  // along the bottom.
  blade_ = right;
  bladeEdges_ = rightEdges;
  for (std::size_t i = right.size(); i-- > 0;) {
    blade_.push_back({-right[i][0], right[i][1]});
    // The mirrored edge from left point i to left point i - 1 is right edge i - 1.
    bladeEdges_.push_back(i > 0 ? rightEdges[i - 1] : EdgeKind::Free);
  }
  bladeFillets_.assign(blade_.size(), p.filletRadius);
  const std::size_t topRight = right.size() - 1, topLeft = right.size();
  bladeFillets_[topRight] = bladeFillets_[topLeft] = 0;  // the blade's top corners stay sharp

  // The slot: every blade edge below the top moved out by Clearance, flanks by nothing, in the
  // blade's order (down the left side, up the right side) and then reversed for the disc.
  const std::size_t m = blade_.size();
  std::vector<Point> linePoint, lineDirection;
  std::vector<EdgeKind> lineKind;
  for (std::size_t e = topLeft; e != topRight; e = (e + 1) % m) {
    const Point a = blade_[e], b = blade_[(e + 1) % m];
    const Point d = minus(b, a);
    const double off = bladeEdges_[e] == EdgeKind::Flank ? 0.0 : p.clearance;
    const double len = length(d);
    linePoint.push_back({a[0] + off * d[1] / len, a[1] - off * d[0] / len});
    lineDirection.push_back(d);
    lineKind.push_back(bladeEdges_[e]);
  }
  const double mouthX = a0 + p.clearance;
  if (!(mouthX < p.outerRadius)) refuse("Neck Width + 2 Clearance must be below the outer radius");
  const double mouthY = std::sqrt(p.outerRadius * p.outerRadius - mouthX * mouthX);
  std::vector<Point> slot{{-mouthX, mouthY}};
  for (std::size_t i = 0; i + 1 < linePoint.size(); ++i)
    slot.push_back(
        intersect(linePoint[i], lineDirection[i], linePoint[i + 1], lineDirection[i + 1]));
  slot.push_back({mouthX, mouthY});
  std::reverse(slot.begin(), slot.end());
  std::reverse(lineKind.begin(), lineKind.end());
  slot_ = slot;
  slotEdges_ = lineKind;
  slotFillets_.assign(slot_.size(), p.filletRadius);
  slotFillets_.front() = slotFillets_.back() = 0;  // the mouth meets the outer arc sharply
  if (!(slot_[1][1] < mouthY))
    refuse("Neck Length = " + numberText(p.neckLength) +
           " puts the first lobe above the slot's mouth: increase it");

  // The slot must stay inside the sector: above the inner radius, off the radial cuts.
  const double halfAngle = 0.5 * p.sectorAngle * M_PI / 180;
  for (const auto& v : slot_) {
    if (!(length(v) > p.innerRadius))
      refuse(
          "the slot reaches the inner radius: increase Outer Radius - Inner Radius or make "
          "the root shorter (Lobes, Lobe Pitch, Neck Length)");
    if (!(std::abs(std::atan2(v[0], v[1])) < 0.9 * halfAngle))
      refuse(
          "the slot comes within 10 % of the sector's radial cuts: increase Sector Angle or "
          "make the root narrower (Neck Width, Lobe Depth)");
  }
  requireValidOutline("blade", blade_, bladeFillets_, true);
  requireValidOutline("slot", slot_, slotFillets_, false);
}

double BladeRootProfile::flankDistance(double x, double y) const {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& f : flanks_)
    d = std::min(d, segmentDistance({x, y}, f[0], f[1]));
  return d;
}

}  // namespace contactlab
