#include "core/io/SceneFile.hpp"

#include "base/InputError.hpp"
#include "core/io/ParameterValidation.hpp"
#include "core/io/YamlParameterList.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace contactlab {
namespace {

// What yaml-cpp says less plainly: a tab in the indentation (YAML indents with spaces) and an
// empty file.
void checkLayout(const std::string& yaml, const std::string& label) {
  std::istringstream in(yaml);
  std::string line;
  int number = 0;
  bool content = false;
  while (std::getline(in, line)) {
    ++number;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    content = true;
    const std::size_t tab = line.find('\t');
    if (tab != std::string::npos && tab < first)
      throw InputError(label + ": line " + std::to_string(number) +
                       ": a tab in the indentation (YAML indents with spaces)");
  }
  if (!content) throw InputError(label + ": the file is empty; a scene starts with 'contactlab:'");
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
  checkLayout(yaml, label);
  return finish(parseYamlParameterList(yaml, label), label, overrides);
}

SceneFile readSceneFile(const std::string& path, const std::vector<std::string>& overrides) {
  if (std::filesystem::is_directory(path))
    throw InputError("scene file '" + path + "' is a directory, not a file");
  if (!std::filesystem::is_regular_file(path))
    throw InputError("scene file '" + path + "' does not exist");
  std::ifstream in(path);
  if (!in) throw InputError("cannot read scene file '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  return readSceneText(text.str(), path, overrides);
}

}  // namespace contactlab
