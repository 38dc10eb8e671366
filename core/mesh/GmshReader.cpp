#include "core/mesh/GmshReader.hpp"

#include "core/mesh/GeoScriptCheck.hpp"
#include "core/mesh/GmshExtract.hpp"
#include "core/mesh/GmshModel.hpp"

#include <gmsh.h>

#include <filesystem>
#include <stdexcept>

namespace contactlab {

Mesh readGmshFile(const std::string& path, double sizeFactor, int elementOrder) {
  // gmsh only prints an error for a missing file and reads other formats by extension, so
  // both are checked here to give a clear message.
  const std::filesystem::path file(path);
  if (!std::filesystem::exists(file))
    throw std::invalid_argument("mesh file '" + path + "' does not exist");
  if (!std::filesystem::is_regular_file(file))
    throw std::invalid_argument("mesh file '" + path + "' is not a regular file");
  const bool script = file.extension() == ".geo";
  if (file.extension() != ".msh" && !script)
    throw std::invalid_argument("mesh file '" + path +
                                "' ends in neither .msh nor .geo; contactlab reads gmsh .msh "
                                "files (format 2.2 or 4.x) and meshes gmsh .geo scripts");
  if (!script && (sizeFactor != 1.0 || elementOrder != 0))
    throw std::invalid_argument("mesh file '" + path +
                                "': Size Factor and Element Order are for a .geo script, which "
                                "contactlab meshes; a .msh file is read as it is");
  if (!(sizeFactor > 0) || elementOrder < 0 || elementOrder > 2)
    throw std::invalid_argument("mesh file '" + path +
                                "': Size Factor must be > 0 and Element Order 0, 1 or 2");
  // A script that would write, run a program or end the process is refused before it runs.
  if (script) checkGeoScript(path);
  const std::string label = "mesh file '" + path + "'";
  return inGmshModel("gmsh could not " + std::string(script ? "mesh " : "read ") + label, [&] {
    gmsh::merge(path);
    if (script) {
      // The script's own options first (merge ran it), then the overrides.
      if (sizeFactor != 1.0) gmsh::option::setNumber("Mesh.MeshSizeFactor", sizeFactor);
      if (elementOrder > 0) gmsh::option::setNumber("Mesh.ElementOrder", elementOrder);
      gmsh::model::mesh::generate(gmsh::model::getDimension());
    }
    return meshFromGmshModel(path, label, NodeIds::gmshTags);
  });
}

}  // namespace contactlab
