#pragma once
// Reading a scene file: YAML with one top-level key `contactlab:` read by yaml-cpp into a
// ParameterList (core/io/YamlParameterList), plus command-line overrides. Validation against the registries happens in
// the app (apps/SceneSchema), which knows every module.
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <string>
#include <vector>

namespace contactlab {

struct SceneFile {
  std::string path;       // as given
  std::string directory;  // for relative paths inside the scene (mesh files)
  std::string name;       // the scene's `Name`, or the file's stem
  Teuchos::RCP<Teuchos::ParameterList> params;
};

// Throws InputError: "scene file 'x.yaml' does not exist", "malformed YAML in 'x.yaml' at line
// 3 column 7: ...", "x.yaml: the top-level key must be 'contactlab'".
SceneFile readSceneFile(const std::string& path, const std::vector<std::string>& overrides = {});

// The same from text in memory (the embedded default scene, tests).
SceneFile readSceneText(const std::string& yaml, const std::string& label,
                        const std::vector<std::string>& overrides = {});

}  // namespace contactlab
