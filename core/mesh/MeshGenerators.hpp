#pragma once
// Built-in meshes, generated in-process with gmsh's OpenCASCADE kernel on the calling rank
// (broadcast them with broadcastMesh). `elementType` is a contactlab element type name
// (ElementType.hpp); order-2 types are complete (tri6, quad9, tet10, hex27) or serendipity
// (quad8, hex20). Structured generators give exactly the requested number of cells. Invalid
// parameters throw std::invalid_argument naming the generator, the parameter and the valid
// choices. Group names are listed with each generator.
#include "core/mesh/Mesh.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace contactlab {

// [x0, x0+Lx] x [y0, y0+Ly], nx*ny quads (tri: each quad split in two, 2*nx*ny cells).
// Types: tri3 tri6 quad4 quad8 quad9. Block "body"; boundaries "bottom", "right", "top",
// "left" (lines); points "corner-bl", "corner-br", "corner-tr", "corner-tl". A non-zero
// topShift shears it into a parallelogram: x += topShift * (y - y0) / Ly (an inclined strut).
struct RectangleParams {
  std::array<double, 2> origin{0.0, 0.0};
  std::array<double, 2> lengths{1.0, 1.0};
  std::array<int, 2> divisions{1, 1};
  double topShift = 0.0;
  std::string elementType = "quad4";
  // When set, the rectangle is mapped bilinearly onto this quadrilateral (x0 y0 ... x3 y3 for
  // the corners bottom-left, bottom-right, top-right, top-left; convex, counter-clockwise):
  // Cook's membrane. Element sides stay straight; the boundary names keep their corners.
  std::optional<std::array<double, 8>> corners;
};
Mesh generateRectangle(const RectangleParams& p);

// The annular sector a <= r <= b, 0 <= theta <= Angle (degrees, counter-clockwise from +x) about
// `centre`: nr x nt structured quads (tri: each split in two, 2 nr nt cells), radial grid lines
// on rays, circumferential ones on circles; order-2 nodes sit at the rays' midpoints and
// exactly on the arcs (the arc's angular midpoint). radialGrading is the ratio of the
// outermost ring's radial size to the innermost's (1: uniform, > 1: finer at the inner radius;
// sizes in geometric progression). Types: tri3 tri6 quad4 quad8 quad9. Block "body";
// boundaries "inner" (r = a), "outer" (r = b), "start" (theta = 0), "end" (theta = Angle);
// points "corner-inner-start", "corner-outer-start", "corner-outer-end", "corner-inner-end".
// Angle = 360 closes the ring: the seam's nodes are shared and "start", "end" and the "-end"
// corners do not exist. An element spans at most 90 degrees (nt >= Angle / 90).
struct RingSectorParams {
  std::array<double, 2> centre{0.0, 0.0};
  double innerRadius = 1.0;
  double outerRadius = 2.0;
  double angle = 90.0;
  int radialDivisions = 4;
  int circumferentialDivisions = 4;
  double radialGrading = 1.0;
  std::string elementType = "quad8";
};
Mesh generateRingSector(const RingSectorParams& p);
// The nr + 1 radii of the grid's circles, a to b, sizes in geometric progression with
// last / first = grading.
std::vector<double> ringSectorRadii(double innerRadius, double outerRadius, int divisions,
                                    double grading);

// Box origin + [0,Lx]x[0,Ly]x[0,Lz], nx*ny*nz hexes (tet: each hex split into 6 tets of a
// transfinite volume, 6*nx*ny*nz cells). Types: tet4 tet10 hex8 hex20 hex27. Block "body";
// faces "xmin", "xmax", "ymin", "ymax", "zmin", "zmax".
struct BoxParams {
  std::array<double, 3> origin{0.0, 0.0, 0.0};
  std::array<double, 3> lengths{1.0, 1.0, 1.0};
  std::array<int, 3> divisions{1, 1, 1};
  std::string elementType = "hex8";
  // When set, (x, y) are mapped bilinearly onto this quadrilateral as in RectangleParams
  // (a slab of Cook's membrane); z keeps origin[2] + [0, Lz].
  std::optional<std::array<double, 8>> xyCorners;
};
Mesh generateBox(const BoxParams& p);

// Mesh size as a function of the distance d to the contact point: sizeContact for
// d <= fineRadius, then growing linearly to sizeFar over transitionLength.
struct ContactGrading {
  double sizeContact = 0.05;
  double sizeFar = 0.25;
  double fineRadius = 0.1;
  double transitionLength = 0.5;
};

// Lower half of the disc of `radius` around `centre`: flat side "flat" on y = centre_y, arc
// "curved" below touching y = centre_y - radius at the contact point (centre_x, centre_y - R),
// which is always a mesh node (point group "contact-point"). Unstructured, graded towards the
// contact point. Types: tri3 tri6 quad4 quad8 quad9 (quads: all-quad blossom recombination).
// Block "body".
struct HalfDiscParams {
  std::array<double, 2> centre{0.0, 1.0};
  double radius = 1.0;
  ContactGrading grading;
  std::string elementType = "tri3";
};
Mesh generateHalfDisc(const HalfDiscParams& p);

// Two bodies touching at one point, meshed separately (disjoint nodes): an upper half disc
// ("roller": flat side up, arc down, lowest point at `contact`) on a base that is either the
// mirrored half disc ("disc": two elastically similar cylinders) or a block of width x height
// whose top's middle is the contact point ("block"). Graded towards the contact point.
// Blocks "roller", "base"; boundaries "roller-flat", "roller-curved", "base-top" (the base's
// contact side: arc or top edge), "base-bottom" (its flat side or bottom edge), and for a block
// "base-left", "base-right". Types as generateHalfDisc.
struct RollerOnBaseParams {
  std::array<double, 2> contact{0.0, 0.0};
  double radius = 1.0;
  std::string base = "block";  // "block" or "disc"
  double baseWidth = 2.0;      // block only
  double baseHeight = 1.0;     // block only
  ContactGrading grading;
  std::string elementType = "quad4";
};
Mesh generateRollerOnBase(const RollerOnBaseParams& p);

// Lower half of the ball of `radius` around `centre`: flat face "flat" on z = centre_z, curved
// face "curved" touching z = centre_z - radius at the contact point, a mesh node (point group
// "contact-point"), away from the sphere's poles and seams. Unstructured, graded towards the
// contact point. Types: tet4 tet10, and hex8 hex20 hex27 (each tet split into 4 hexes: valid
// but poorer quality). Block "body".
struct HalfSphereParams {
  std::array<double, 3> centre{0.0, 0.0, 1.0};
  double radius = 1.0;
  ContactGrading grading{0.1, 0.3, 0.1, 0.5};
  std::string elementType = "tet4";
  // "block": a separately meshed box under the sphere, its top face through the lowest point
  // (width x width, centred there, `baseHeight` deep). Block 'base'; faces 'base-top',
  // 'base-bottom', 'base-sides'.
  std::string base = "none";
  double baseWidth = 2.0;
  double baseHeight = 1.0;
};
Mesh generateHalfSphere(const HalfSphereParams& p);

// Patch-test geometry: two separately meshed (non-matching, disjoint nodes) blocks of width
// Lx. "lower" is origin + [0,Lx]x[0,lowerHeight]; "upper" starts `gap` above its top (gap < 0
// is an overlap) and is upperHeight high. upperRotationDeg turns the upper block's mesh about
// the vertical axis through its centre (counter-clockwise, degrees). Types: tri3 tri6 quad4
// quad8 quad9. Blocks "lower", "upper"; boundaries "lower-bottom", "lower-top", "lower-left",
// "lower-right", "upper-bottom", "upper-top", "upper-left", "upper-right" (names refer to the
// unrotated blocks). alongX puts the blocks side by side instead, "upper" to the right of
// "lower": the heights and the gap are then along x and the width along y, so the interface is
// vertical (lower-right against upper-left): two concentric rings of an axisymmetric model.
struct StackedBlocks2DParams {
  std::array<double, 2> origin{0.0, 0.0};
  double width = 1.0;
  double lowerHeight = 1.0;
  double upperHeight = 1.0;
  double gap = 0.0;
  std::array<int, 2> lowerDivisions{2, 2};
  std::array<int, 2> upperDivisions{3, 3};
  double upperRotationDeg = 0.0;
  std::string elementType = "quad4";
  bool alongX = false;
};
Mesh generateStackedBlocks2D(const StackedBlocks2DParams& p);

// 3D version: footprint [0,Lx]x[0,Ly] from origin, blocks stacked along z, rotation about the
// vertical (z) axis through the upper block's centre. Types: tet4 tet10 hex8 hex20 hex27.
// Blocks "lower", "upper"; faces "<block>-bottom" (zmin), "<block>-top" (zmax),
// "<block>-xmin", "<block>-xmax", "<block>-ymin", "<block>-ymax" for block lower and upper.
struct StackedBlocks3DParams {
  std::array<double, 3> origin{0.0, 0.0, 0.0};
  std::array<double, 2> footprint{1.0, 1.0};
  double lowerHeight = 1.0;
  double upperHeight = 1.0;
  double gap = 0.0;
  std::array<int, 3> lowerDivisions{2, 2, 2};
  std::array<int, 3> upperDivisions{3, 3, 3};
  double upperRotationDeg = 0.0;
  // The upper block's footprint extends this far beyond the lower's on each side (so that,
  // rotated, it still covers the lower's top face).
  double upperMargin = 0.0;
  std::string elementType = "hex8";
};
Mesh generateStackedBlocks3D(const StackedBlocks3DParams& p);

// A turbine blade's fir-tree root in its disc slot, plane strain, two separately meshed bodies
// (disjoint nodes). The disc is the annular sector Inner Radius <= r <= Outer Radius about the
// origin, Sector Angle wide, symmetric about the +y axis (the radial axis of the blade); the
// slot is cut into it from the outer radius. The blade root has `lobes` lobes per side, symmetric
// about x = 0: from the top, a shank of Neck Width, then per lobe a contact flank going outward
// and down at Flank Angle from the x axis (Lobe Depth wide), a vertical tip land, a lower flank
// back in to the next neck; each neck is Taper narrower (per side) than the one above, lobes are
// Lobe Pitch apart radially. The disc's slot follows the root: its contact flanks coincide with
// the blade's (zero initial gap), every other slot face stands Clearance off the blade's. Every
// corner of the root and slot is rounded with Fillet Radius. The blade's shank rises Blade
// Height above the disc's outer radius. Mesh size is Size Flank within Fine Distance of the
// contact flanks, growing linearly to Size Far over Transition Length. Types: tri3 tri6 quad4
// quad8 quad9 (quads: all-quad blossom recombination). Blocks "blade", "disc"; boundaries
// "blade-flanks", "disc-flanks" (the contact flanks with the fillets at their ends),
// "blade-top", "blade-free"
// (the blade's other slot faces), "disc-slot" (the slot's other faces), "disc-inner",
// "disc-outer", "disc-sides" (the sector's two radial cuts), "disc-side-left", "disc-side-right"
// (each alone).
struct BladeRootParams {
  int lobes = 2;
  double innerRadius = 40.0;
  double outerRadius = 100.0;
  double sectorAngle = 24.0;  // degrees, whole sector
  double neckWidth = 12.0;    // the shank's full width
  double neckLength = 4.0;    // from the outer radius (on the axis) down to the first flank
  double lobeDepth = 3.0;     // per side, beyond the neck above it
  double lobePitch = 7.0;     // radial distance between lobes
  double flankAngle = 30.0;   // degrees from the x axis
  double tipLand = 1.0;       // vertical length of a lobe's tip
  double taper = 1.5;         // per side, each neck narrower than the one above
  double filletRadius = 0.5;
  double clearance = 0.2;
  double bladeHeight = 15.0;  // shank above the outer radius
  double sizeFlank = 0.5;
  double sizeFar = 5.0;
  double fineDistance = 1.0;
  double transitionLength = 20.0;
  std::string elementType = "quad4";
  // hex8 hex20 hex27: the section swept along z over [0, thickness] in `layers` layers; the
  // groups above become the swept faces, plus "blade-back", "disc-back" (z = 0) and
  // "blade-front", "disc-front" (z = thickness).
  double thickness = 10.0;
  int layers = 4;
};
Mesh generateBladeRoot(const BladeRootParams& p);

// The ironing benchmark of Puso & Laursen (2004), two separately meshed bodies (disjoint
// nodes): a slab [0, Slab Length] x [0, Slab Width] x [0, Slab Height] (structured) and a die,
// a cylindrical shell segment with its axis along y: outer radius Die Radius, Die Thickness
// thick, Die Width wide (centred on the slab's width, so a wider die overhangs both sides),
// spanning Die Angle degrees centred on straight down. The die's lowest outer point is at
// x = Die Start, Gap above the slab's top. Die Divisions are through the thickness, along the
// width and along the arc. Types: tet4 tet10 hex8 hex20 hex27. Blocks "slab", "die"; faces
// "slab-top", "slab-bottom", "slab-xmin", "slab-xmax", "slab-ymin", "slab-ymax", "die-outer"
// (the convex contact face), "die-inner" (its back, where a tool would hold it), "die-sides"
// (y faces), "die-ends" (the arc's ends).
struct DieOnSlabParams {
  std::array<double, 3> slabLengths{9.0, 4.0, 3.0};
  std::array<int, 3> slabDivisions{18, 8, 6};
  double dieRadius = 3.0;
  double dieThickness = 0.2;
  double dieWidth = 5.2;
  double dieAngle = 180.0;
  double dieStart = 2.5;
  double gap = 0.0;
  std::array<int, 3> dieDivisions{1, 10, 24};
  std::string elementType = "hex8";
};
Mesh generateDieOnSlab(const DieOnSlabParams& p);

// A steam-generator tube in its tubesheet hole, a sector of Angle degrees about the z axis (the
// tube's), two separately meshed bodies (disjoint nodes): the tube, inner radius Tube Outer
// Diameter / 2 - Tube Wall to outer radius Tube Outer Diameter / 2, and the tubesheet around it,
// from the hole's radius (the tube's outer radius + Clearance) to Sheet Outer Radius (the
// ligament as an equivalent sleeve), both over z in [0, Thickness]. Structured hexes: Tube
// Radial Divisions through the wall, Sheet Radial Divisions through the sleeve (sizes growing
// outward by Sheet Radial Grading), Circumferential Divisions along the arc, and Axial Divisions
// below, along and above the expansion zone [Expansion Start, Expansion End] (grid planes at its
// ends); the tubesheet may have its own arc and axial divisions (Sheet Circumferential
// Divisions, Sheet Axial Divisions, uniform along z). Types: hex8 hex20 hex27. Blocks "tube",
// "tubesheet"; boundaries "tube-inner", "tube-inner-expanded" (its part in the expansion zone,
// where the expansion pressure acts), "tube-outer", "hole" (the contact pair), "sheet-outer",
// "tube-bottom", "tube-top", "sheet-bottom", "sheet-top" (z = 0, z = Thickness), "cut-start" (the
// plane y = 0, both bodies) and "cut-end" (the plane at Angle, both bodies): the sector's symmetry
// planes.
struct TubeInTubesheetParams {
  double tubeOuterDiameter = 19.05;
  double tubeWall = 1.09;
  double clearance = 0.1;
  double sheetOuterRadius = 15.0;
  double thickness = 20.0;
  double expansionStart = 2.5;
  double expansionEnd = 17.5;
  double angle = 10.0;  // degrees
  int tubeRadialDivisions = 2;
  int sheetRadialDivisions = 6;
  double sheetRadialGrading = 4.0;
  int circumferentialDivisions = 2;
  std::array<int, 3> axialDivisions{2, 12, 2};  // below, along, above the expansion zone
  // The tubesheet's own divisions along the arc and along z (uniform); 0: the tube's. Meshes
  // that do not match keep slave nodes off the master's nodes and edges.
  int sheetCircumferentialDivisions = 3;
  int sheetAxialDivisions = 11;
  std::string elementType = "hex8";
};
Mesh generateTubeInTubesheet(const TubeInTubesheetParams& p);

}  // namespace contactlab
