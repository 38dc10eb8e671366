#include "core/mesh/MeshSourceRegistry.hpp"

#include "base/InputError.hpp"
#include "core/mesh/ElementEstimate.hpp"
#include "core/mesh/GmshReader.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include <filesystem>

namespace contactlab {
namespace {

using Teuchos::Array;
using Teuchos::ParameterList;
using Teuchos::RCP;

RCP<const Teuchos::ParameterEntryValidator> oneOf(const std::vector<std::string>& names) {
  return Teuchos::rcp(new Teuchos::StringValidator(Array<std::string>(names)));
}

template <class T>
Array<T> arrayOf(const std::vector<T>& values) {
  return Array<T>(values);
}

const std::vector<std::string> k2D{"tri3", "tri6", "quad4", "quad8", "quad9"};
const std::vector<std::string> k3D{"tet4", "tet10", "hex8", "hex20", "hex27"};

template <std::size_t N, class T>
std::array<T, N> fixed(const ParameterList& p, const std::string& key) {
  const auto& a = p.get<Array<T>>(key);
  if (a.size() != N)
    throw std::invalid_argument(key + " must have " + std::to_string(N) + " components");
  std::array<T, N> out{};
  for (std::size_t i = 0; i < N; ++i)
    out[i] = a[i];
  return out;
}

void addGrading(ParameterList& p, const ContactGrading& g) {
  p.set("Size Contact", g.sizeContact, "Element size near the contact point");
  p.set("Size Far", g.sizeFar, "Element size far from the contact point");
  p.set("Fine Radius", g.fineRadius, "Distance from the contact point meshed at Size Contact");
  p.set("Transition Length", g.transitionLength,
        "Distance over which the size grows from Size Contact to Size Far");
}

void addElementLimit(ParameterList& p) {
  p.set(kMaxElementsKey, kDefaultMaxElements,
        "Refuse before meshing when the estimated element count exceeds this (> 0): a request "
        "that would exhaust memory ends in a sentence, not in bad_alloc");
}

// The generator's parameters, checked against its element limit before gmsh runs.
template <class Params>
const Params& withinLimit(const std::string& generator, const ParameterList& p, const Params& g) {
  requireElementLimit(generator, estimateElements(g), p.get<int>(kMaxElementsKey));
  return g;
}

ContactGrading grading(const ParameterList& p) {
  return {p.get<double>("Size Contact"), p.get<double>("Size Far"), p.get<double>("Fine Radius"),
          p.get<double>("Transition Length")};
}

RCP<const ParameterList> fileParameters() {
  auto p = Teuchos::rcp(new ParameterList("file"));
  p->set("Path", "",
         "gmsh .msh file (format 4 or 2.2), or a gmsh .geo script that contactlab meshes with "
         "its own Mesh options (a script, or one it includes, that writes a file, runs a "
         "program or exits is refused: doc/scenes.md, The output folder); relative to the "
         "scene file's folder");
  p->set("Size Factor", 1.0,
         ".geo only: scales every element size of the script (gmsh's Mesh.MeshSizeFactor; "
         "0.5 halves them), for a mesh-convergence study with --set (> 0)");
  p->set("Element Order", 0,
         ".geo only: 1 (linear) or 2 (quadratic) elements whatever the script says (gmsh's "
         "Mesh.ElementOrder; its Mesh.SecondOrderIncomplete still picks quad8 or quad9); 0: "
         "the script's");
  return p;
}

RCP<const ParameterList> rectangleParameters() {
  auto p = Teuchos::rcp(new ParameterList("rectangle"));
  p->set("Origin", arrayOf<double>({0.0, 0.0}), "Lower-left corner");
  p->set("Lx", 1.0, "Width");
  p->set("Ly", 1.0, "Height");
  p->set("nx", 4, "Divisions along x");
  p->set("ny", 4, "Divisions along y");
  p->set("Element", "quad4", "Element type (tri3 splits each quad in two)", oneOf(k2D));
  p->set("Top Shift", 0.0,
         "Shears the rectangle into a parallelogram: the top edge moves this much along x, "
         "every node by Top Shift * (y - y0) / Ly");
  addElementLimit(*p);
  return p;
}

RCP<const ParameterList> quadrilateralParameters() {
  auto p = Teuchos::rcp(new ParameterList("quadrilateral"));
  p->set("Corners", arrayOf<double>({0.0, 0.0, 48.0, 44.0, 48.0, 60.0, 0.0, 44.0}),
         "x y of the corners bottom-left, bottom-right, top-right, top-left (8 numbers, "
         "counter-clockwise, convex); the default is Cook's membrane");
  p->set("nx", 4, "Divisions from the left side to the right side");
  p->set("ny", 4, "Divisions from the bottom side to the top side");
  p->set("Element", "quad4", "Element type (tri3 splits each quad in two)", oneOf(k2D));
  addElementLimit(*p);
  return p;
}

RCP<const ParameterList> ringSectorParameters() {
  auto p = Teuchos::rcp(new ParameterList("ring-sector"));
  RingSectorParams d;
  p->set("Centre", arrayOf<double>({d.centre[0], d.centre[1]}), "Centre of the circles");
  p->set("Inner Radius", d.innerRadius, "Inner radius a (> 0)");
  p->set("Outer Radius", d.outerRadius, "Outer radius b (> Inner Radius)");
  p->set("Angle", d.angle,
         "Opening angle in degrees, in (0, 360], counter-clockwise from the +x axis; 360 closes "
         "the ring (no 'start', 'end')");
  p->set("Radial Divisions", d.radialDivisions, "Divisions from the inner to the outer radius");
  p->set("Circumferential Divisions", d.circumferentialDivisions,
         "Divisions along the arcs (at least Angle / 90: an element spans at most 90 degrees)");
  p->set("Radial Grading", d.radialGrading,
         "Ratio of the outermost element's radial size to the innermost's (> 0; 1: uniform, "
         "> 1: finer at the inner radius), sizes in geometric progression");
  p->set("Element", d.elementType, "Element type (tri3 splits each quad in two)", oneOf(k2D));
  addElementLimit(*p);
  return p;
}

RCP<const ParameterList> boxParameters() {
  auto p = Teuchos::rcp(new ParameterList("box"));
  p->set("Origin", arrayOf<double>({0.0, 0.0, 0.0}), "Corner with the smallest coordinates");
  p->set("Lx", 1.0, "Length along x");
  p->set("Ly", 1.0, "Length along y");
  p->set("Lz", 1.0, "Length along z");
  p->set("nx", 2, "Divisions along x");
  p->set("ny", 2, "Divisions along y");
  p->set("nz", 2, "Divisions along z");
  p->set("Element", "hex8", "Element type (tets: 6 per hex cell)", oneOf(k3D));
  p->set("XY Corners", Array<double>(),
         "Optional: x y of four corners (bottom-left, bottom-right, top-right, top-left; "
         "convex, counter-clockwise) onto which the box's x-y section is mapped bilinearly, "
         "e.g. [0, 0, 48, 44, 48, 60, 0, 44] for a slab of Cook's membrane; Lx and Ly then "
         "only set the grid's proportions. Empty: the box itself");
  addElementLimit(*p);
  return p;
}

RCP<const ParameterList> halfDiscParameters() {
  auto p = Teuchos::rcp(new ParameterList("half-disc"));
  HalfDiscParams d;
  p->set("Centre", arrayOf<double>({d.centre[0], d.centre[1]}),
         "Centre of the disc; the flat side lies at its height");
  p->set("Radius", d.radius, "Radius");
  addGrading(*p, d.grading);
  p->set("Element", "tri3", "Element type", oneOf(k2D));
  addElementLimit(*p);
  return p;
}

RCP<const ParameterList> rollerOnBaseParameters() {
  auto p = Teuchos::rcp(new ParameterList("roller-on-base"));
  RollerOnBaseParams d;
  p->set("Contact Point", arrayOf<double>({d.contact[0], d.contact[1]}),
         "Where the roller touches the base");
  p->set("Radius", d.radius, "Radius of the roller (and of a disc base)");
  p->set("Base", d.base,
         "'block' (a rectangle under the roller) or 'disc' (the mirrored half "
         "disc: two elastically similar cylinders)",
         oneOf({"block", "disc"}));
  p->set("Base Width", d.baseWidth, "Block base: width (centred on the contact point)");
  p->set("Base Height", d.baseHeight, "Block base: height");
  addGrading(*p, d.grading);
  p->set("Element", "quad4", "Element type", oneOf(k2D));
  addElementLimit(*p);
  return p;
}

RCP<const ParameterList> halfSphereParameters() {
  auto p = Teuchos::rcp(new ParameterList("half-sphere"));
  HalfSphereParams d;
  p->set("Centre", arrayOf<double>({d.centre[0], d.centre[1], d.centre[2]}),
         "Centre of the ball; the flat face lies at its height");
  p->set("Radius", d.radius, "Radius");
  addGrading(*p, d.grading);
  p->set("Element", "tet4", "Element type (hexes: each tet split into 4)", oneOf(k3D));
  p->set("Base", d.base,
         "'none', or 'block': a separately meshed box under the sphere, touching it at its "
         "lowest point (a two-body Hertz contact)",
         oneOf({"none", "block"}));
  p->set("Base Width", d.baseWidth, "Block base: side of its square top, centred under the sphere");
  p->set("Base Height", d.baseHeight, "Block base: depth");
  addElementLimit(*p);
  return p;
}

RCP<const ParameterList> stacked2DParameters() {
  auto p = Teuchos::rcp(new ParameterList("stacked-blocks-2d"));
  p->set("Origin", arrayOf<double>({0.0, 0.0}), "Lower-left corner of the lower block");
  p->set("Width", 1.0, "Width of both blocks");
  p->set("Lower Height", 1.0, "Height of the lower block");
  p->set("Upper Height", 1.0, "Height of the upper block");
  p->set("Gap", 0.0, "Initial gap between the blocks (negative: overlap)");
  p->set("Lower Divisions", arrayOf<int>({2, 2}), "nx, ny of the lower block");
  p->set("Upper Divisions", arrayOf<int>({3, 3}), "nx, ny of the upper block");
  p->set("Upper Rotation", 0.0, "Rotation of the upper block's mesh, degrees");
  p->set("Stacking", "y",
         "'y': the upper block above the lower; 'x': side by side, the upper block to the right "
         "(the heights and the gap along x, Width along y, the interface vertical: two "
         "concentric rings of an axisymmetric model)",
         oneOf({"y", "x"}));
  p->set("Element", "quad4", "Element type", oneOf(k2D));
  addElementLimit(*p);
  return p;
}

RCP<const ParameterList> stacked3DParameters() {
  auto p = Teuchos::rcp(new ParameterList("stacked-blocks-3d"));
  p->set("Origin", arrayOf<double>({0.0, 0.0, 0.0}), "Lowest corner of the lower block");
  p->set("Footprint", arrayOf<double>({1.0, 1.0}), "Lx, Ly of both blocks");
  p->set("Lower Height", 1.0, "Height of the lower block");
  p->set("Upper Height", 1.0, "Height of the upper block");
  p->set("Gap", 0.0, "Initial gap between the blocks (negative: overlap)");
  p->set("Lower Divisions", arrayOf<int>({2, 2, 2}), "nx, ny, nz of the lower block");
  p->set("Upper Divisions", arrayOf<int>({3, 3, 3}), "nx, ny, nz of the upper block");
  p->set("Upper Rotation", 0.0, "Rotation of the upper block's mesh about z, degrees");
  p->set("Upper Margin", 0.0,
         "How far the upper block's footprint extends beyond the lower's on each side");
  p->set("Element", "hex8", "Element type", oneOf(k3D));
  addElementLimit(*p);
  return p;
}

RCP<const ParameterList> tubeInTubesheetParameters() {
  auto p = Teuchos::rcp(new ParameterList("tube-in-tubesheet"));
  TubeInTubesheetParams d;
  p->set("Tube Outer Diameter", d.tubeOuterDiameter, "The tube's outer diameter (> 0)");
  p->set("Tube Wall", d.tubeWall, "The tube's wall thickness (> 0, < its outer radius)");
  p->set("Clearance", d.clearance,
         "Radial gap between the tube and its hole before expansion (>= 0)");
  p->set("Sheet Outer Radius", d.sheetOuterRadius,
         "Outer radius of the tubesheet sleeve around the hole (the ligament as an equivalent "
         "cylinder; > the hole's radius)");
  p->set("Thickness", d.thickness, "Axial length of tube and tubesheet, z in [0, Thickness]");
  p->set("Expansion Start", d.expansionStart, "z where the expansion zone begins (>= 0)");
  p->set("Expansion End", d.expansionEnd,
         "z where the expansion zone ends (> Expansion Start, <= Thickness)");
  p->set("Angle", d.angle, "Sector angle in degrees, in (0, 90]");
  p->set("Tube Radial Divisions", d.tubeRadialDivisions, "Divisions through the tube's wall");
  p->set("Sheet Radial Divisions", d.sheetRadialDivisions, "Divisions through the sleeve");
  p->set("Sheet Radial Grading", d.sheetRadialGrading,
         "Ratio of the sleeve's outermost element's radial size to its innermost's (> 0)");
  p->set("Circumferential Divisions", d.circumferentialDivisions, "Divisions along the arc");
  p->set("Axial Divisions",
         arrayOf<int>({d.axialDivisions[0], d.axialDivisions[1], d.axialDivisions[2]}),
         "Divisions below, along and above the expansion zone (0 where that part is empty)");
  p->set("Sheet Circumferential Divisions", d.sheetCircumferentialDivisions,
         "The tubesheet's divisions along the arc; 0: the tube's");
  p->set("Sheet Axial Divisions", d.sheetAxialDivisions,
         "The tubesheet's divisions along z, uniform; 0: the tube's");
  p->set("Element", d.elementType, "Element type", oneOf({"hex8", "hex20", "hex27"}));
  addElementLimit(*p);
  return p;
}

RCP<const ParameterList> dieOnSlabParameters() {
  auto p = Teuchos::rcp(new ParameterList("die-on-slab"));
  DieOnSlabParams d;
  const auto [l, w, h] = d.slabLengths;
  p->set("Slab Length", l, "Slab length along x, the sliding direction (> 0)");
  p->set("Slab Width", w, "Slab width along y (> 0)");
  p->set("Slab Height", h,
         "Slab height along z (> 0); its bottom is z = 0, its top z = Slab Height");
  p->set("Slab Divisions",
         arrayOf<int>({d.slabDivisions[0], d.slabDivisions[1], d.slabDivisions[2]}),
         "nx, ny, nz of the slab");
  p->set("Die Radius", d.dieRadius, "Outer radius of the die's cylindrical face (> 0)");
  p->set("Die Thickness", d.dieThickness, "Radial thickness of the die (> 0, < Die Radius)");
  p->set("Die Width", d.dieWidth,
         "Die length along its axis (y), centred on the slab's width; wider than the slab, it "
         "overhangs both sides");
  p->set("Die Angle", d.dieAngle,
         "Arc of the die in degrees, in (0, 180], centred on straight down (180: a half cylinder)");
  p->set("Die Start", d.dieStart, "x of the die's lowest point, on the slab: [0, Slab Length]");
  p->set("Gap", d.gap, "Initial gap between the die's lowest point and the slab's top");
  p->set("Die Divisions", arrayOf<int>({d.dieDivisions[0], d.dieDivisions[1], d.dieDivisions[2]}),
         "Divisions of the die through its thickness, along its width and along its arc (an "
         "element spans at most 30 degrees of arc)");
  p->set("Element", d.elementType, "Element type (tets: each hex split into 6)", oneOf(k3D));
  addElementLimit(*p);
  return p;
}

RCP<const ParameterList> bladeRootParameters() {
  auto p = Teuchos::rcp(new ParameterList("blade-root"));
  BladeRootParams d;
  p->set("Lobes", d.lobes, "Lobes per side of the fir-tree root (1 to 4)");
  p->set("Inner Radius", d.innerRadius, "Inner radius of the disc sector (> 0), about the origin");
  p->set("Outer Radius", d.outerRadius,
         "Outer radius of the disc sector (> Inner Radius); the slot opens there");
  p->set("Sector Angle", d.sectorAngle,
         "Opening of the disc sector in degrees, in (0, 180), symmetric about the +y axis (the "
         "blade's radial axis); the slot must keep 10 % of it clear on each side");
  p->set("Neck Width", d.neckWidth, "Full width of the blade's shank and top neck (> 0)");
  p->set("Neck Length", d.neckLength,
         "Radial distance from the outer radius (on the axis) down to the first lobe's flank "
         "(> 0)");
  p->set("Lobe Depth", d.lobeDepth,
         "How far each lobe stands out beyond the neck above it, per side (> 0)");
  p->set("Lobe Pitch", d.lobePitch,
         "Radial distance between successive lobes (> Lobe Depth * tan(Flank Angle) + Tip "
         "Land, so that the lower flank descends)");
  p->set("Flank Angle", d.flankAngle,
         "Angle of the contact flanks from the circumferential (x) direction, degrees in "
         "(0, 75): 0 would be a flat shoulder carrying the load radially");
  p->set("Tip Land", d.tipLand, "Radial length of each lobe's straight tip (> 0)");
  p->set("Taper", d.taper,
         "How much narrower each neck is than the one above, per side (>= 0; Lobes * Taper < "
         "Neck Width / 2)");
  p->set("Fillet Radius", d.filletRadius,
         "Radius of the rounding of every corner of the root and the slot (>= 0; 0: sharp)");
  p->set("Clearance", d.clearance,
         "Gap between the blade and the slot on every face but the contact flanks (> 0), "
         "which touch with zero gap");
  p->set("Blade Height", d.bladeHeight,
         "How far the blade's shank rises above the outer radius to 'blade-top' (> 0)");
  p->set("Size Flank", d.sizeFlank, "Element size within Fine Distance of the contact flanks");
  p->set("Size Far", d.sizeFar, "Element size far from the flanks (>= Size Flank)");
  p->set("Fine Distance", d.fineDistance, "Distance from the flanks meshed at Size Flank (>= 0)");
  p->set("Transition Length", d.transitionLength,
         "Distance over which the size grows from Size Flank to Size Far");
  p->set("Element", d.elementType,
         "Element type (quads: all-quad recombination); hex8, hex20, hex27 sweep the section "
         "along z (3D)",
         oneOf({"tri3", "tri6", "quad4", "quad8", "quad9", "hex8", "hex20", "hex27"}));
  p->set("Thickness", d.thickness, "hex elements: axial length of the swept model (> 0)");
  p->set("Layers", d.layers, "hex elements: element layers along z (>= 1)");
  addElementLimit(*p);
  return p;
}

}  // namespace

MeshSourceRegistry& meshSourceRegistry() {
  static MeshSourceRegistry registry("mesh source");
  return registry;
}

void registerMeshSources() {
  auto& r = meshSourceRegistry();
  r.add({"file",
         "A gmsh .msh file (format 4 or 2.2) or .geo script (meshed at load); physical "
         "groups name blocks and boundaries, and its node tags name the nodes in contact.csv "
         "and the VTK output (a generator's nodes are named by index + 1).",
         fileParameters, [](const ParameterList& p, const std::string& dir) {
           std::filesystem::path path = p.get<std::string>("Path");
           if (path.empty()) throw InputError("Mesh/file/Path is empty");
           if (path.is_relative()) path = std::filesystem::path(dir) / path;
           return std::make_unique<Mesh>(readGmshFile(path.lexically_normal().string(),
                                                      p.get<double>("Size Factor"),
                                                      p.get<int>("Element Order")));
         }});
  r.add({"rectangle",
         "Structured rectangle. Block 'body'; boundaries 'bottom', 'right', 'top', 'left'.",
         rectangleParameters, [](const ParameterList& p, const std::string&) {
           RectangleParams g;
           g.origin = fixed<2, double>(p, "Origin");
           g.lengths = {p.get<double>("Lx"), p.get<double>("Ly")};
           g.divisions = {p.get<int>("nx"), p.get<int>("ny")};
           g.elementType = p.get<std::string>("Element");
           g.topShift = p.get<double>("Top Shift");
           return std::make_unique<Mesh>(generateRectangle(withinLimit("rectangle", p, g)));
         }});
  r.add({"quadrilateral",
         "Structured mesh of a quadrilateral with straight sides (a bilinear map of the unit "
         "square; Cook's membrane by default). Block 'body'; boundaries 'bottom', 'right', "
         "'top', 'left' (the sides from each corner to the next), points 'corner-bl', "
         "'corner-br', 'corner-tr', 'corner-tl'.",
         quadrilateralParameters, [](const ParameterList& p, const std::string&) {
           RectangleParams g;
           g.corners = fixed<8, double>(p, "Corners");
           g.divisions = {p.get<int>("nx"), p.get<int>("ny")};
           g.elementType = p.get<std::string>("Element");
           return std::make_unique<Mesh>(generateRectangle(withinLimit("quadrilateral", p, g)));
         }});
  r.add({"ring-sector",
         "Structured annular sector a <= r <= b, 0 <= theta <= Angle (a thick tube's section), "
         "mid-side nodes on the arcs. Block 'body'; boundaries 'inner', 'outer', 'start' "
         "(theta = 0), 'end' (theta = Angle), points 'corner-inner-start', "
         "'corner-outer-start', 'corner-outer-end', 'corner-inner-end'.",
         ringSectorParameters, [](const ParameterList& p, const std::string&) {
           RingSectorParams g;
           g.centre = fixed<2, double>(p, "Centre");
           g.innerRadius = p.get<double>("Inner Radius");
           g.outerRadius = p.get<double>("Outer Radius");
           g.angle = p.get<double>("Angle");
           g.radialDivisions = p.get<int>("Radial Divisions");
           g.circumferentialDivisions = p.get<int>("Circumferential Divisions");
           g.radialGrading = p.get<double>("Radial Grading");
           g.elementType = p.get<std::string>("Element");
           return std::make_unique<Mesh>(generateRingSector(withinLimit("ring-sector", p, g)));
         }});
  r.add({"box",
         "Structured box. Block 'body'; faces 'xmin', 'xmax', 'ymin', 'ymax', 'zmin', 'zmax'.",
         boxParameters, [](const ParameterList& p, const std::string&) {
           BoxParams g;
           g.origin = fixed<3, double>(p, "Origin");
           g.lengths = {p.get<double>("Lx"), p.get<double>("Ly"), p.get<double>("Lz")};
           g.divisions = {p.get<int>("nx"), p.get<int>("ny"), p.get<int>("nz")};
           g.elementType = p.get<std::string>("Element");
           if (!p.get<Array<double>>("XY Corners").empty())
             g.xyCorners = fixed<8, double>(p, "XY Corners");
           return std::make_unique<Mesh>(generateBox(withinLimit("box", p, g)));
         }});
  r.add({"half-disc",
         "Lower half of a disc (Hertz cylinder), graded towards the lowest point. Block 'body'; "
         "boundaries 'flat' (top), 'curved' (arc), point 'contact-point'.",
         halfDiscParameters, [](const ParameterList& p, const std::string&) {
           HalfDiscParams g;
           g.centre = fixed<2, double>(p, "Centre");
           g.radius = p.get<double>("Radius");
           g.grading = grading(p);
           g.elementType = p.get<std::string>("Element");
           return std::make_unique<Mesh>(generateHalfDisc(withinLimit("half-disc", p, g)));
         }});
  r.add({"roller-on-base",
         "Two bodies touching at one point (two-body Hertz, Cattaneo-Mindlin): a half disc "
         "'roller' on a 'base' block or mirrored half disc, meshed separately, graded towards "
         "the contact. Boundaries 'roller-flat', 'roller-curved', 'base-top', 'base-bottom' "
         "(block: also 'base-left', 'base-right').",
         rollerOnBaseParameters, [](const ParameterList& p, const std::string&) {
           RollerOnBaseParams g;
           g.contact = fixed<2, double>(p, "Contact Point");
           g.radius = p.get<double>("Radius");
           g.base = p.get<std::string>("Base");
           g.baseWidth = p.get<double>("Base Width");
           g.baseHeight = p.get<double>("Base Height");
           g.grading = grading(p);
           g.elementType = p.get<std::string>("Element");
           return std::make_unique<Mesh>(generateRollerOnBase(withinLimit("roller-on-base", p, g)));
         }});
  r.add({"half-sphere",
         "Lower half of a ball (Hertz sphere), graded towards the lowest point, optionally on a "
         "block. Block 'body'; faces 'flat' (top), 'curved', point 'contact-point' (block: also "
         "'base', 'base-top', 'base-bottom', 'base-sides').",
         halfSphereParameters, [](const ParameterList& p, const std::string&) {
           HalfSphereParams g;
           g.centre = fixed<3, double>(p, "Centre");
           g.radius = p.get<double>("Radius");
           g.grading = grading(p);
           g.elementType = p.get<std::string>("Element");
           g.base = p.get<std::string>("Base");
           g.baseWidth = p.get<double>("Base Width");
           g.baseHeight = p.get<double>("Base Height");
           return std::make_unique<Mesh>(generateHalfSphere(withinLimit("half-sphere", p, g)));
         }});
  r.add({"blade-root",
         "A turbine blade's fir-tree root in its disc slot (plane strain), meshed separately, "
         "graded towards the contact flanks. Blocks 'blade', 'disc'; boundaries "
         "'blade-flanks', 'disc-flanks' (the lobes' contact flanks with the fillets at their "
         "ends), 'blade-top', 'blade-free' "
         "and 'disc-slot' (the other faces of root and slot), 'disc-inner', 'disc-outer', "
         "'disc-sides' (the sector's radial cuts), and each alone, 'disc-side-left' and "
         "'disc-side-right' (for Symmetry conditions); hex elements sweep it along z, adding "
         "'blade-back', 'disc-back' (z = 0), 'blade-front', 'disc-front'.",
         bladeRootParameters, [](const ParameterList& p, const std::string&) {
           BladeRootParams g;
           g.lobes = p.get<int>("Lobes");
           g.innerRadius = p.get<double>("Inner Radius");
           g.outerRadius = p.get<double>("Outer Radius");
           g.sectorAngle = p.get<double>("Sector Angle");
           g.neckWidth = p.get<double>("Neck Width");
           g.neckLength = p.get<double>("Neck Length");
           g.lobeDepth = p.get<double>("Lobe Depth");
           g.lobePitch = p.get<double>("Lobe Pitch");
           g.flankAngle = p.get<double>("Flank Angle");
           g.tipLand = p.get<double>("Tip Land");
           g.taper = p.get<double>("Taper");
           g.filletRadius = p.get<double>("Fillet Radius");
           g.clearance = p.get<double>("Clearance");
           g.bladeHeight = p.get<double>("Blade Height");
           g.sizeFlank = p.get<double>("Size Flank");
           g.sizeFar = p.get<double>("Size Far");
           g.fineDistance = p.get<double>("Fine Distance");
           g.transitionLength = p.get<double>("Transition Length");
           g.elementType = p.get<std::string>("Element");
           g.thickness = p.get<double>("Thickness");
           g.layers = p.get<int>("Layers");
           return std::make_unique<Mesh>(generateBladeRoot(withinLimit("blade-root", p, g)));
         }});
  r.add({"die-on-slab",
         "Puso & Laursen's 3D ironing: a slab and a cylindrical shell-segment die above it, its "
         "axis along y, meshed separately (structured). Blocks 'slab', 'die'; faces 'slab-top', "
         "'slab-bottom', 'slab-xmin', 'slab-xmax', 'slab-ymin', 'slab-ymax', 'die-outer' (the "
         "convex contact face), 'die-inner' (its back), 'die-sides', 'die-ends'.",
         dieOnSlabParameters, [](const ParameterList& p, const std::string&) {
           DieOnSlabParams g;
           g.slabLengths = {p.get<double>("Slab Length"), p.get<double>("Slab Width"),
                            p.get<double>("Slab Height")};
           g.slabDivisions = fixed<3, int>(p, "Slab Divisions");
           g.dieRadius = p.get<double>("Die Radius");
           g.dieThickness = p.get<double>("Die Thickness");
           g.dieWidth = p.get<double>("Die Width");
           g.dieAngle = p.get<double>("Die Angle");
           g.dieStart = p.get<double>("Die Start");
           g.gap = p.get<double>("Gap");
           g.dieDivisions = fixed<3, int>(p, "Die Divisions");
           g.elementType = p.get<std::string>("Element");
           return std::make_unique<Mesh>(generateDieOnSlab(withinLimit("die-on-slab", p, g)));
         }});
  r.add({"stacked-blocks-2d",
         "Two separately meshed blocks, one on the other (contact patch test). Blocks 'lower', "
         "'upper'; boundaries '<block>-bottom', '-top', '-left', '-right'.",
         stacked2DParameters, [](const ParameterList& p, const std::string&) {
           StackedBlocks2DParams g;
           g.origin = fixed<2, double>(p, "Origin");
           g.width = p.get<double>("Width");
           g.lowerHeight = p.get<double>("Lower Height");
           g.upperHeight = p.get<double>("Upper Height");
           g.gap = p.get<double>("Gap");
           g.lowerDivisions = fixed<2, int>(p, "Lower Divisions");
           g.upperDivisions = fixed<2, int>(p, "Upper Divisions");
           g.upperRotationDeg = p.get<double>("Upper Rotation");
           g.elementType = p.get<std::string>("Element");
           g.alongX = p.get<std::string>("Stacking") == "x";
           return std::make_unique<Mesh>(
               generateStackedBlocks2D(withinLimit("stacked-blocks-2d", p, g)));
         }});
  r.add({"tube-in-tubesheet",
         "A steam-generator tube in its tubesheet hole, a sector about the tube's axis z, two "
         "separately meshed bodies of structured hexes. Blocks 'tube', 'tubesheet'; boundaries "
         "'tube-inner', 'tube-inner-expanded' (its part in the expansion zone), 'tube-outer' "
         "and 'hole' (the contact pair), 'sheet-outer', 'tube-bottom', 'tube-top', "
         "'sheet-bottom', 'sheet-top' (z = 0, Thickness), 'cut-start' (the plane y = 0) and "
         "'cut-end' (the plane at Angle), both bodies': the sector's symmetry planes.",
         tubeInTubesheetParameters, [](const ParameterList& p, const std::string&) {
           TubeInTubesheetParams g;
           g.tubeOuterDiameter = p.get<double>("Tube Outer Diameter");
           g.tubeWall = p.get<double>("Tube Wall");
           g.clearance = p.get<double>("Clearance");
           g.sheetOuterRadius = p.get<double>("Sheet Outer Radius");
           g.thickness = p.get<double>("Thickness");
           g.expansionStart = p.get<double>("Expansion Start");
           g.expansionEnd = p.get<double>("Expansion End");
           g.angle = p.get<double>("Angle");
           g.tubeRadialDivisions = p.get<int>("Tube Radial Divisions");
           g.sheetRadialDivisions = p.get<int>("Sheet Radial Divisions");
           g.sheetRadialGrading = p.get<double>("Sheet Radial Grading");
           g.circumferentialDivisions = p.get<int>("Circumferential Divisions");
           g.axialDivisions = fixed<3, int>(p, "Axial Divisions");
           g.sheetCircumferentialDivisions = p.get<int>("Sheet Circumferential Divisions");
           g.sheetAxialDivisions = p.get<int>("Sheet Axial Divisions");
           g.elementType = p.get<std::string>("Element");
           return std::make_unique<Mesh>(
               generateTubeInTubesheet(withinLimit("tube-in-tubesheet", p, g)));
         }});
  r.add({"stacked-blocks-3d",
         "Two separately meshed boxes stacked along z. Blocks 'lower', 'upper'; faces "
         "'<block>-bottom', '-top', '-xmin', '-xmax', '-ymin', '-ymax'.",
         stacked3DParameters, [](const ParameterList& p, const std::string&) {
           StackedBlocks3DParams g;
           g.origin = fixed<3, double>(p, "Origin");
           g.footprint = fixed<2, double>(p, "Footprint");
           g.lowerHeight = p.get<double>("Lower Height");
           g.upperHeight = p.get<double>("Upper Height");
           g.gap = p.get<double>("Gap");
           g.lowerDivisions = fixed<3, int>(p, "Lower Divisions");
           g.upperDivisions = fixed<3, int>(p, "Upper Divisions");
           g.upperRotationDeg = p.get<double>("Upper Rotation");
           g.upperMargin = p.get<double>("Upper Margin");
           g.elementType = p.get<std::string>("Element");
           return std::make_unique<Mesh>(
               generateStackedBlocks3D(withinLimit("stacked-blocks-3d", p, g)));
         }});
}

}  // namespace contactlab
