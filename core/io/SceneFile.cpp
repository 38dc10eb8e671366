#include "core/io/SceneFile.hpp"

#include "base/InputError.hpp"
#include "core/io/ParameterValidation.hpp"

#include <Teuchos_YamlParameterListHelpers.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

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

// What Teuchos' parser does not say with a line: an empty file, a tab in the indentation (YAML
// indents with spaces), a key given twice in one block mapping. Flow mappings ({a: 1, a: 2})
// and block scalars (| and >) are left to the parser.
void checkLayout(const std::string& yaml, const std::string& label) {
  std::istringstream in(yaml);
  std::string line;
  int number = 0;
  bool content = false;
  // Open block mappings: their indentation and keys (with the line that gave each).
  std::vector<std::pair<std::size_t, std::map<std::string, int>>> open;
  std::size_t scalarIndent = std::string::npos;  // inside a block scalar deeper than this
  int flowDepth = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    content = true;
    const std::size_t tab = line.find('\t');
    if (tab != std::string::npos && tab < first)
      throw InputError(label + ": line " + std::to_string(number) +
                       ": a tab in the indentation (YAML indents with spaces)");
    if (scalarIndent != std::string::npos) {
      if (first > scalarIndent) continue;
      scalarIndent = std::string::npos;
    }
    // Inside a flow collection ({...} or [...]) spread over lines: the parser's business.
    const int depthBefore = flowDepth;
    for (char c : line)
      flowDepth += (c == '{' || c == '[') - (c == '}' || c == ']');
    if (depthBefore > 0) continue;
    if (line[first] == '-' || line[first] == '{' || line[first] == '[') {
      // A sequence item starts: the mappings of the previous item are closed.
      while (!open.empty() && open.back().first > first)
        open.pop_back();
      continue;
    }
    const std::size_t colon = line.find(':', first);
    if (colon == std::string::npos || (colon + 1 < line.size() && line[colon + 1] != ' ')) continue;
    std::string key = line.substr(first, colon - first);
    while (!key.empty() && key.back() == ' ')
      key.pop_back();
    if (key.empty() || key[0] == '"' || key[0] == '\'') continue;
    while (!open.empty() && open.back().first > first)
      open.pop_back();
    if (open.empty() || open.back().first < first) open.push_back({first, {}});
    auto [it, inserted] = open.back().second.emplace(key, number);
    if (!inserted)
      throw InputError(label + ": line " + std::to_string(number) + ": the key '" + key +
                       "' is given twice in one section (first at line " +
                       std::to_string(it->second) + ")");
    std::string rest = line.substr(colon + 1);
    const std::size_t r = rest.find_first_not_of(' ');
    if (r != std::string::npos && (rest[r] == '|' || rest[r] == '>')) scalarIndent = first;
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
  Teuchos::RCP<Teuchos::ParameterList> params;
  try {
    params = Teuchos::getParametersFromYamlString(yaml);
  } catch (const std::exception& e) {
    throw InputError("malformed YAML in '" + label + "': " + parserMessage(e.what()));
  }
  return finish(params, label, overrides);
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
