#pragma once
// `contactlab list [AXIS]`: the Markdown reference of a scene's sections and of every registry,
// each key with its default and doc string, wrapped at 100 columns (doc/scenes.md embeds the
// whole of it, tests/app/check_scenes_doc.py). AXIS picks one part: `sections`, or one
// registry (mesh, material, formulation, discretization, linear-solver).
#include <string>
#include <vector>

namespace contactlab {

// The AXIS names `contactlab list` takes, in the reference's order.
std::vector<std::string> referenceAxes();

// The whole reference (axis empty) or one axis' part. Throws InputError for an unknown axis,
// naming the valid ones.
std::string sceneReference(const std::string& axis = "");

}  // namespace contactlab
