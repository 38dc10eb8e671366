#include "core/mesh/GmshReader.hpp"

#include "core/mesh/GmshExtract.hpp"
#include "core/mesh/GmshModel.hpp"

#include <gmsh.h>

#include <filesystem>
#include <stdexcept>

namespace contactlab {

Mesh readGmshFile(const std::string& path) {
  // gmsh only prints an error for a missing file and reads other formats by extension, so
  // both are checked here to give a clear message.
  const std::filesystem::path file(path);
  if (!std::filesystem::exists(file))
    throw std::invalid_argument("mesh file '" + path + "' does not exist");
  if (!std::filesystem::is_regular_file(file))
    throw std::invalid_argument("mesh file '" + path + "' is not a regular file");
  if (file.extension() != ".msh")
    throw std::invalid_argument("mesh file '" + path +
                                "' does not end in .msh; contactlab reads gmsh .msh files "
                                "(format 2.2 or 4.x)");
  const std::string label = "mesh file '" + path + "'";
  return inGmshModel("gmsh could not read " + label, [&] {
    gmsh::merge(path);
    return meshFromGmshModel(path, label, NodeIds::gmshTags);
  });
}

}  // namespace contactlab
