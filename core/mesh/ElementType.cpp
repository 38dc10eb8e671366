#include "core/mesh/ElementType.hpp"

#include <stdexcept>

namespace contactlab {
namespace {

using ET = ElementType;
const ElementTypeInfo kInfo[] = {
    {ET::Point1, "point1", 0, 1, 0, 15, 1, ET::Point1, ET::Point1},
    {ET::Line2, "line2", 1, 2, 1, 1, 3, ET::Point1, ET::Line2},
    {ET::Line3, "line3", 1, 3, 2, 8, 21, ET::Point1, ET::Line2},
    {ET::Tri3, "tri3", 2, 3, 1, 2, 5, ET::Line2, ET::Tri3},
    {ET::Tri6, "tri6", 2, 6, 2, 9, 22, ET::Line3, ET::Tri3},
    {ET::Quad4, "quad4", 2, 4, 1, 3, 9, ET::Line2, ET::Quad4},
    {ET::Quad8, "quad8", 2, 8, 2, 16, 23, ET::Line3, ET::Quad4},
    {ET::Quad9, "quad9", 2, 9, 2, 10, 28, ET::Line3, ET::Quad4},
    {ET::Tet4, "tet4", 3, 4, 1, 4, 10, ET::Tri3, ET::Tet4},
    {ET::Tet10, "tet10", 3, 10, 2, 11, 24, ET::Tri6, ET::Tet4},
    {ET::Hex8, "hex8", 3, 8, 1, 5, 12, ET::Quad4, ET::Hex8},
    {ET::Hex20, "hex20", 3, 20, 2, 17, 25, ET::Quad8, ET::Hex8},
    {ET::Hex27, "hex27", 3, 27, 2, 12, 29, ET::Quad9, ET::Hex8},
};

}  // namespace

const ElementTypeInfo& info(ElementType type) {
  return kInfo[static_cast<int>(type)];
}

ElementType elementTypeFromName(const std::string& name) {
  std::string valid;
  for (const auto& i : kInfo) {
    if (name == i.name) return i.type;
    valid += (valid.empty() ? "" : ", ") + std::string(i.name);
  }
  throw std::invalid_argument("unknown element type '" + name + "'; valid types: " + valid);
}

ElementType elementTypeFromGmsh(int gmshType) {
  for (const auto& i : kInfo)
    if (i.gmshType == gmshType) return i.type;
  throw std::invalid_argument("gmsh element type " + std::to_string(gmshType) +
                              " is not supported by contactlab (supported: point, line2, "
                              "line3, tri3, tri6, quad4, quad8, quad9, tet4, tet10, hex8, hex20, "
                              "hex27)");
}

int cornerCount(ElementType type) {
  return info(info(type).linear).nodes;
}

std::vector<std::string> solidElementTypeNames() {
  std::vector<std::string> names;
  for (const auto& i : kInfo)
    if (i.dim >= 2) names.emplace_back(i.name);
  return names;
}

}  // namespace contactlab
