#pragma once
// Element types known to contactlab. Node ordering everywhere inside contactlab is gmsh's
// (https://gmsh.info/doc/texinfo/gmsh.html#Node-ordering); VTK ordering is applied only when
// writing results.
#include <string>
#include <vector>

namespace contactlab {

enum class ElementType {
  Point1,
  Line2,
  Line3,
  Tri3,
  Tri6,
  Quad4,
  Quad8,
  Quad9,
  Tet4,
  Tet10,
  Hex8,
  Hex20,
  Hex27
};

struct ElementTypeInfo {
  ElementType type;
  const char* name;    // contactlab's name, used in scene files: "quad8", "hex27", ...
  int dim;             // topological dimension
  int nodes;           // number of nodes
  int order;           // polynomial order of the geometry (1 or 2)
  int gmshType;        // gmsh element type id
  int vtkType;         // VTK cell type id
  ElementType facet;   // type of its facets (Point1 for lines, itself for points)
  ElementType linear;  // the same shape on its corners only (itself for a linear type)
};

const ElementTypeInfo& info(ElementType type);

// Number of corner (vertex) nodes, those of info(type).linear; they come first in gmsh's node
// order.
int cornerCount(ElementType type);

// Throws std::invalid_argument naming the valid choices when `name` is unknown.
ElementType elementTypeFromName(const std::string& name);

// Throws std::invalid_argument when gmsh's type id is not supported by contactlab.
ElementType elementTypeFromGmsh(int gmshType);

// Names of the volume (2D and 3D) element types, in the enum's order.
std::vector<std::string> solidElementTypeNames();

}  // namespace contactlab
