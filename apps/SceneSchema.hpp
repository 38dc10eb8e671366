#pragma once
// The scene file's schema: which keys a scene may hold, each with a default and a doc string.
// Typed sections (Mesh, Materials/<block>, Contact/<zone>/Formulation, Linear Solver) take `Type:
// name` and a sibling sublist named after the type whose valid parameters come from that axis'
// registry; named sections (Materials, Dirichlet, Loads, Contact, Output/Probes) hold one sublist
// per user-chosen name.
#include <Teuchos_ParameterList.hpp>

#include <string>

namespace contactlab {

// Registers every module's registries (idempotent).
void registerAll();

// The valid list for this user scene (typed sections resolved with the user's Type entries).
// Throws InputError for an unknown Type name or a section that should be a sublist.
Teuchos::ParameterList sceneSchema(const Teuchos::ParameterList& scene, const std::string& where);

// Validates `scene` in place (unknown keys, types, enumerations) and fills in the defaults.
void validateScene(Teuchos::ParameterList& scene, const std::string& where);

// Markdown reference of every section and registry, with defaults and doc strings (printed by
// `contactlab list`; doc/scenes.md embeds it).
std::string sceneReference();

}  // namespace contactlab
