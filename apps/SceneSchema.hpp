#pragma once
// The scene file's schema: which keys a scene may hold, each with a default and a doc string.
// Typed sections (Mesh, Materials/<block>, Contact/<zone>/Formulation, Linear Solver) take `Type:
// name` and a sibling sublist named after the type whose valid parameters come from that axis'
// registry; named sections (Materials, Dirichlet, Loads, Contact, Output/Probes) hold one sublist
// per user-chosen name.
#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace contactlab {

// Registers every module's registries (idempotent).
void registerAll();

// The valid list for this user scene (typed sections resolved with the user's Type entries).
// Throws InputError for an unknown Type name or a section that should be a sublist.
Teuchos::ParameterList sceneSchema(const Teuchos::ParameterList& scene, const std::string& where);

// Validates `scene` in place (unknown keys, types, enumerations) and fills in the defaults.
void validateScene(Teuchos::ParameterList& scene, const std::string& where);

// The sections of a scene that are not a registry's, in the reference's order (`contactlab
// list`, SceneReference.hpp): a heading (the key path, <name> for a user-chosen name), an
// optional introduction, and the valid list with its defaults and doc strings.
struct SceneSection {
  std::string heading;
  std::string intro;
  Teuchos::ParameterList valid;
};
std::vector<SceneSection> sceneSections();

}  // namespace contactlab
