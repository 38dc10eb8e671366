#pragma once
// Internal to core/mesh: pieces shared by the built-in generators. All functions act on gmsh's
// current model and must run inside inGmshModel.
#include "base/NumberText.hpp"
#include "core/mesh/ElementType.hpp"
#include "core/mesh/Mesh.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <array>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace contactlab {

struct ElementSpec {
  ElementType type;
  bool simplex;      // tri/tet (else quad/hex, obtained by recombination)
  int order;         // 1 or 2
  bool serendipity;  // quad8/hex20
};

// Throws std::invalid_argument "<generator> generator: element type 'x' is not supported;
// valid choices: ..." unless `name` is one of `allowed`.
ElementSpec elementSpec(const std::string& generator, const std::string& name,
                        std::initializer_list<ElementType> allowed);

// Parameter validation, std::invalid_argument naming generator and parameter.
void requirePositive(const std::string& generator, const std::string& param, double value);
void requireDivisions(const std::string& generator, const std::string& param, int value);
void requireGrading(const std::string& generator, const ContactGrading& grading);
// The checks a graded round body (half-disc, roller-on-base, half-sphere) starts with: its
// element type among `allowed`, a positive Radius, a valid grading. Returns the type's spec.
ElementSpec roundBodySpec(const std::string& generator, const std::string& elementType,
                          std::initializer_list<ElementType> allowed, double radius,
                          const ContactGrading& grading);
// The base of a generator whose body may stand on a block: `base` must be one of `choices`
// (the message names them in this order, one of them "block"), and a block needs a positive
// width and height. Returns whether the base is the block.
bool requireBase(const std::string& generator, const std::string& base,
                 const std::array<const char*, 2>& choices, double width, double height);

// Sets every gmsh option the generators depend on, so earlier gmsh use cannot leak in.
void resetMeshOptions();

// Raises the order of the generated mesh to spec.order (complete or serendipity).
void applyOrder(const ElementSpec& spec);

// Adds a named physical group.
void addGroup(int dim, const std::vector<int>& tags, const std::string& name);

std::array<double, 3> centerOfMass(int dim, int tag);

// Transfinite (structured) rectangle in z = 0, synchronised; recombine for quads.
struct RectangleEntities {
  int surface;
  std::array<int, 4> sides;    // bottom, right, top, left
  std::array<int, 4> corners;  // bottom-left, bottom-right, top-right, top-left
};
RectangleEntities addStructuredRectangle(const std::array<double, 2>& origin,
                                         const std::array<double, 2>& lengths,
                                         const std::array<int, 2>& divisions, bool recombine);

// The whole gmsh run of a structured rectangle generator: block "body", the sides (bottom,
// right, top, left) and corners (bottom-left, bottom-right, top-right, top-left) as named
// boundary groups, cells of spec's type. Runs in its own scratch model (inGmshModel).
Mesh meshStructuredRectangle(const ElementSpec& spec, const std::array<double, 2>& origin,
                             const std::array<double, 2>& lengths,
                             const std::array<int, 2>& divisions,
                             const std::array<const char*, 4>& sides,
                             const std::array<const char*, 4>& corners, const std::string& source);

// Transfinite box, synchronised; hexes with recombine, else 6 tets per hex.
struct BoxEntities {
  int volume;
  std::array<int, 6> faces;  // xmin, xmax, ymin, ymax, zmin, zmax
};
BoxEntities addStructuredBox(const std::array<double, 3>& origin,
                             const std::array<double, 3>& lengths,
                             const std::array<int, 3>& divisions, bool recombine);

// Generates the mesh of dimension `dim` with the element size size(x, y, z).
void generateWithSize(int dim, const std::function<double(double x, double y, double z)>& size);

// Generates the mesh of dimension `dim` with sizes graded from `point` (scaled by
// `sizeFactor`, e.g. 2 when a later subdivision halves every edge).
void generateGraded(int dim, const std::array<double, 3>& point, const ContactGrading& grading,
                    double sizeFactor);

// Throws std::invalid_argument unless corners (x0 y0 ... x3 y3) list a convex quadrilateral
// counter-clockwise, so that the bilinear map below is one to one.
void requireConvexQuadrilateral(const std::string& generator, const std::array<double, 8>& corners);
// Maps every node's (x, y) from the rectangle origin + [0, Lx] x [0, Ly] bilinearly onto the
// quadrilateral `corners` (z unchanged). Straight grid lines of a structured mesh stay straight
// and mid-side nodes on them stay in the middle.
void mapOntoQuadrilateral(Mesh& mesh, const std::array<double, 2>& origin,
                          const std::array<double, 2>& lengths,
                          const std::array<double, 8>& corners);

// Blossom full-quad recombination can in principle leave triangles; never hand them out:
// throws std::runtime_error naming `source` when the 2D mesh holds any non-quadrilateral.
void requireAllQuads(const std::string& source);

// Rotates the nodes of block `name` about the vertical axis through (cx, cy), in degrees.
void rotateBlockAboutZ(Mesh& mesh, const std::string& name, double cx, double cy, double degrees);

// "tri3, tri6, ..." for messages.
std::string typeList(std::initializer_list<ElementType> types);

}  // namespace contactlab
