#pragma once
// A gmsh .geo script is a program: besides geometry it may write files (Save, Print, Printf
// ... > "file", CreateDir, an option naming a file gmsh writes), run programs (System,
// SystemCall, OnelabRun, SendToServer) or end the process (Exit). contactlab meshes a scene's
// script when it reads the scene, `validate` included, and promises to write nothing but its
// results folder, so such a script is refused before gmsh runs it. The scripts it Includes or
// Merges are checked the same way, by their paths relative to the including file (gmsh's
// rule); a path that is computed (StrCat, Sprintf, a variable) cannot be checked and is
// refused too. Geometry, meshing options and data files read (a .msh, a CAD file) are not
// affected.
#include <string>

namespace contactlab {

// Throws std::invalid_argument with one sentence naming the file, the line and the command.
void checkGeoScript(const std::string& path);

}  // namespace contactlab
