#include "apps/SceneReference.hpp"

#include "apps/SceneSchema.hpp"
#include "base/InputError.hpp"
#include "base/NumberText.hpp"
#include "core/io/ParameterValidation.hpp"
#include "core/materials/MaterialRegistry.hpp"
#include "core/mesh/MeshSourceRegistry.hpp"
#include "core/problem/ElementTechnology.hpp"
#include "formulations/ContactDiscretizationType.hpp"
#include "formulations/FormulationRegistry.hpp"
#include "linear/LinearSolverRegistry.hpp"

#include <cctype>
#include <functional>
#include <sstream>
#include <vector>

namespace contactlab {
namespace {

using Teuchos::ParameterList;

constexpr std::size_t kWidth = 100;

// A word Markdown would read as the start of a block (a list item, a heading, a quote) at the
// start of a line: never put there by the wrapping.
bool startsBlock(const std::string& word) {
  if (word.empty()) return false;
  if (word == "-" || word == "*" || word == "+" || word[0] == '#' || word[0] == '>' ||
      word[0] == '|' || word == "=" || word.rfind("==", 0) == 0 || word.rfind("--", 0) == 0)
    return true;
  std::size_t digits = 0;
  while (digits < word.size() && std::isdigit(static_cast<unsigned char>(word[digits])))
    ++digits;
  return digits > 0 && digits < word.size() && (word[digits] == '.' || word[digits] == ')');
}

// `text` after `first`, wrapped at kWidth columns, each further line after `indent`; a line
// break in `text` is kept. A word that would start a block goes to the next line with the word
// before it; a word longer than a line has a line of its own.
std::string wrapped(const std::string& first, const std::string& text, const std::string& indent) {
  std::vector<std::string> lines{first};
  std::vector<std::vector<std::string>> words(1);  // each line's words
  const auto length = [&](std::size_t k) {
    std::size_t n = lines[k].size();
    for (const std::string& w : words[k])
      n += w.size() + 1;
    return n - (words[k].empty() ? 0 : 1);
  };
  std::istringstream paragraphs(text);
  bool firstParagraph = true;
  for (std::string paragraph; std::getline(paragraphs, paragraph); firstParagraph = false) {
    if (!firstParagraph) {
      lines.push_back(indent);
      words.emplace_back();
    }
    std::istringstream in(paragraph);
    for (std::string word; in >> word;) {
      std::vector<std::string>& line = words.back();
      if (line.empty() || length(words.size() - 1) + 1 + word.size() <= kWidth) {
        line.push_back(word);
        continue;
      }
      std::vector<std::string> next;
      if (startsBlock(word) && line.size() > 1) {
        next.push_back(line.back());
        line.pop_back();
      }
      next.push_back(word);
      lines.push_back(indent);
      words.push_back(std::move(next));
    }
  }
  std::string out;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    out += lines[k];
    for (std::size_t w = 0; w < words[k].size(); ++w)
      out += (w ? " " : "") + words[k][w];
    out += "\n";
  }
  return out;
}

std::string formatValue(const Teuchos::ParameterEntry& entry) {
  if (entry.isType<double>()) return numberText(Teuchos::getValue<double>(entry));
  if (entry.isType<int>()) return std::to_string(Teuchos::getValue<int>(entry));
  if (entry.isType<bool>()) return Teuchos::getValue<bool>(entry) ? "true" : "false";
  if (entry.isType<std::string>()) return "\"" + Teuchos::getValue<std::string>(entry) + "\"";
  std::string s;
  if (entry.isType<Teuchos::Array<double>>())
    for (double v : Teuchos::getValue<Teuchos::Array<double>>(entry))
      s += (s.empty() ? "" : ", ") + numberText(v);
  else if (entry.isType<Teuchos::Array<int>>())
    for (int v : Teuchos::getValue<Teuchos::Array<int>>(entry))
      s += (s.empty() ? "" : ", ") + std::to_string(v);
  return "[" + s + "]";
}

void describeList(std::ostream& out, const ParameterList& list) {
  for (auto it = list.begin(); it != list.end(); ++it) {
    const auto& entry = list.entry(it);
    const std::string& key = list.name(it);
    if (entry.isList()) {
      if (isPassThrough(list.sublist(key)))
        out << wrapped("- `" + key + "`: a sublist. ", entry.docString(), "  ");
      else
        out << "- `" << key << "`: a sublist (see below)\n";
      continue;
    }
    std::string doc = entry.docString();
    if (auto validator = entry.validator(); !validator.is_null()) {
      if (auto strings = validator->validStringValues(); !strings.is_null()) {
        std::string choices;
        for (const auto& c : *strings)
          choices += (choices.empty() ? "" : ", ") + c;
        doc += ". Choices: " + choices;
      }
    }
    out << wrapped("- `" + key + "` (default `" + formatValue(entry) + "`): ", doc, "  ");
  }
}

template <class RegistryT>
void describeRegistry(std::ostream& out, const RegistryT& registry, const std::string& section) {
  out << "### " << section << " — " << registry.axis() << " registry\n\n";
  for (const auto& name : registry.names()) {
    const auto& entry = registry.get(name);
    out << "#### `" << name << "`\n\n" << wrapped("", entry.doc, "") << "\n";
    const auto valid = entry.validParameters();
    describeList(out, *valid);
    // A law's nested sublists (Temperature Tables) are described under it, with their doc.
    for (auto it = valid->begin(); it != valid->end(); ++it)
      if (valid->entry(it).isList() && !isPassThrough(valid->sublist(valid->name(it)))) {
        out << "\n"
            << wrapped("`" + valid->name(it) + "`: ", valid->entry(it).docString(), "") << "\n";
        describeList(out, valid->sublist(valid->name(it)));
      }
    out << "\n";
  }
}

void describeSections(std::ostream& out) {
  bool first = true;
  for (const SceneSection& section : sceneSections()) {
    out << (first ? "" : "\n") << "### " << section.heading << "\n\n";
    if (!section.intro.empty()) out << wrapped("", section.intro, "") << "\n";
    describeList(out, section.valid);
    first = false;
  }
}

struct Axis {
  std::string name;
  std::function<void(std::ostream&)> describe;
};

// In the reference's order.
const std::vector<Axis>& axes() {
  static const std::vector<Axis> all{
      {"sections", describeSections},
      {"mesh", [](std::ostream& o) { describeRegistry(o, meshSourceRegistry(), "Mesh"); }},
      {"material",
       [](std::ostream& o) { describeRegistry(o, materialRegistry(), "Materials/<block>"); }},
      {"element-technology",
       [](std::ostream& o) {
         describeRegistry(o, elementTechnologyRegistry(), "Materials/<block>/Element Technology");
       }},
      {"formulation",
       [](std::ostream& o) {
         describeRegistry(o, formulationRegistry(), "Contact/<zone>/Formulation");
       }},
      {"discretization",
       [](std::ostream& o) {
         describeRegistry(o, contactDiscretizationRegistry(), "Contact/<zone>/Discretization");
       }},
      {"linear-solver",
       [](std::ostream& o) { describeRegistry(o, linearSolverRegistry(), "Linear Solver"); }}};
  return all;
}

}  // namespace

std::vector<std::string> referenceAxes() {
  std::vector<std::string> names;
  for (const Axis& axis : axes())
    names.push_back(axis.name);
  return names;
}

std::string sceneReference(const std::string& axis) {
  registerAll();
  std::ostringstream out;
  if (axis.empty()) {
    out << "## Sections\n\n";
    describeSections(out);
    out << "\n## Registries\n\n";
    for (const Axis& a : axes())
      if (a.name != "sections") a.describe(out);
    return out.str();
  }
  for (const Axis& a : axes())
    if (a.name == axis) {
      a.describe(out);
      return out.str();
    }
  std::string valid;
  for (const std::string& name : referenceAxes())
    valid += (valid.empty() ? "" : ", ") + name;
  throw InputError("list: unknown axis '" + axis + "'; valid axes: " + valid);
}

}  // namespace contactlab
