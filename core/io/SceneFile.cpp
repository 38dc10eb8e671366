#include "core/io/SceneFile.hpp"

#include "core/io/InputError.hpp"
#include "core/io/ParameterValidation.hpp"

#include <Teuchos_YamlParameterListHelpers.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace contactlab {
namespace {

// Teuchos' parser messages start with "error: Parser failure at line L column C of F" and
// continue with the offending text and an "Expected ..." line; keep position and expectation.
std::string parserMessage(const std::string& what) {
  std::istringstream s(what);
  std::string line, position, expected;
  while (std::getline(s, line)) {
    if (auto p = line.find("at line "); p != std::string::npos && position.empty()) {
      auto q = line.find(" of ", p);
      position = line.substr(p, q == std::string::npos ? std::string::npos : q - p);
    }
    if (line.rfind("Expected", 0) == 0 && expected.empty()) expected = line;
  }
  if (position.empty()) return "it is not valid YAML or has more than one top-level key";
  return position + (expected.empty() ? "" : ": " + expected);
}

SceneFile finish(Teuchos::RCP<Teuchos::ParameterList> params, const std::string& label,
                 const std::vector<std::string>& overrides) {
  if (params->name() != "contactlab")
    throw InputError(label + ": the top-level key must be 'contactlab' (got '" + params->name() +
                     "')");
  for (const auto& o : overrides)
    applyOverride(*params, o);
  SceneFile scene;
  scene.path = label;
  scene.directory = std::filesystem::path(label).parent_path().string();
  if (scene.directory.empty()) scene.directory = ".";
  scene.name = params->isType<std::string>("Name") ? params->get<std::string>("Name")
                                                   : std::filesystem::path(label).stem().string();
  scene.params = params;
  return scene;
}

}  // namespace

SceneFile readSceneText(const std::string& yaml, const std::string& label,
                        const std::vector<std::string>& overrides) {
  Teuchos::RCP<Teuchos::ParameterList> params;
  try {
    params = Teuchos::getParametersFromYamlString(yaml);
  } catch (const std::exception& e) {
    throw InputError("malformed YAML in '" + label + "': " + parserMessage(e.what()));
  }
  return finish(params, label, overrides);
}

SceneFile readSceneFile(const std::string& path, const std::vector<std::string>& overrides) {
  if (!std::filesystem::is_regular_file(path))
    throw InputError("scene file '" + path + "' does not exist");
  std::ifstream in(path);
  if (!in) throw InputError("cannot read scene file '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  return readSceneText(text.str(), path, overrides);
}

}  // namespace contactlab
