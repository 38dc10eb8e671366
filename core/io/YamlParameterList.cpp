#include "core/io/YamlParameterList.hpp"

#include "base/InputError.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_TwoDArray.hpp>

#include <algorithm>
#include <cctype>
#include <climits>
#include <map>
#include <sstream>
#include <vector>
#include <yaml-cpp/yaml.h>

namespace contactlab {
namespace {

// Ordered from the most to the least specific: an array takes the least specific of its items.
enum class ScalarType { Bool = 0, Int = 1, Double = 2, String = 3 };

std::string where(const std::string& label, const YAML::Mark& mark) {
  return label + ": line " + std::to_string(mark.line + 1) + " column " +
         std::to_string(mark.column + 1);
}

// Each whole text parsed, nothing left over (Teuchos' own rule).
template <typename T>
bool parses(const std::string& text, T& value) {
  std::istringstream in(text);
  in >> std::noskipws >> value;
  return !in.fail() && in.eof();
}

bool isBool(const std::string& text, bool& value) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const bool yes = lower == "true" || lower == "yes";
  if (!yes && lower != "false" && lower != "no") return false;
  value = yes;
  return true;
}

ScalarType scalarType(const YAML::Node& node) {
  // yaml-cpp tags a plain scalar "?" and a quoted or block one "!".
  if (node.Tag() != "?") return ScalarType::String;
  const std::string& text = node.Scalar();
  bool b;
  long long i;
  double d;
  if (isBool(text, b)) return ScalarType::Bool;
  if (parses(text, i) && i >= INT_MIN && i <= INT_MAX) return ScalarType::Int;
  if (parses(text, d)) return ScalarType::Double;
  return ScalarType::String;
}

template <typename T>
T scalarAs(const YAML::Node& node) {
  T value{};
  parses(node.Scalar(), value);
  return value;
}

template <>
std::string scalarAs<std::string>(const YAML::Node& node) {
  return node.Scalar();
}

template <>
int scalarAs<int>(const YAML::Node& node) {
  return static_cast<int>(scalarAs<long long>(node));
}

class Converter {
 public:
  explicit Converter(std::string label) : label_(std::move(label)) {}

  void mapping(const YAML::Node& node, Teuchos::ParameterList& list, const std::string& path,
               int depth = 1) {
    // Aliases can make a graph of the tree (a mapping holding an alias of itself) or expand
    // it without bound (aliases of aliases): a scene's tree is shallow and small.
    if (depth > kMaxDepth)
      throw InputError(where(label_, node.Mark()) + ": sections nested deeper than " +
                       std::to_string(kMaxDepth) + " (an alias of an enclosing section?)" +
                       inside(path));
    countEntries(node.size());
    std::map<std::string, int> seen;  // key -> its line
    for (const auto& item : node) {
      const YAML::Node& keyNode = item.first;
      if (!keyNode.IsScalar())
        throw InputError(where(label_, keyNode.Mark()) + ": a key must be a plain name" +
                         inside(path));
      const std::string key = keyNode.Scalar();
      auto [first, inserted] = seen.emplace(key, keyNode.Mark().line + 1);
      if (!inserted)
        throw InputError(label_ + ": line " + std::to_string(keyNode.Mark().line + 1) +
                         ": the key '" + key + "' is given twice in one section (first at line " +
                         std::to_string(first->second) + ")" + inside(path));
      value(item.second, list, key, path.empty() ? key : path + "/" + key, depth);
    }
  }

 private:
  static constexpr int kMaxDepth = 32;
  static constexpr std::size_t kMaxEntries = 1000000;
  std::string label_;
  std::size_t entries_ = 0;

  void countEntries(std::size_t n) {
    if ((entries_ += n) > kMaxEntries)
      throw InputError(label_ + ": more than " + std::to_string(kMaxEntries) +
                       " entries once its aliases are expanded");
  }

  static std::string inside(const std::string& path) {
    return path.empty() ? "" : " (in '" + path + "')";
  }

  void value(const YAML::Node& node, Teuchos::ParameterList& list, const std::string& key,
             const std::string& path, int depth) {
    switch (node.Type()) {
      case YAML::NodeType::Null:
      case YAML::NodeType::Undefined:
        list.sublist(key);
        return;
      case YAML::NodeType::Map:
        mapping(node, list.sublist(key), path, depth + 1);
        return;
      case YAML::NodeType::Scalar:
        scalar(node, list, key);
        return;
      case YAML::NodeType::Sequence:
        sequence(node, list, key, path);
        return;
    }
  }

  static void scalar(const YAML::Node& node, Teuchos::ParameterList& list, const std::string& key) {
    switch (scalarType(node)) {
      case ScalarType::Bool: {
        bool b = false;
        isBool(node.Scalar(), b);
        list.set(key, b);
        return;
      }
      case ScalarType::Int:
        list.set(key, scalarAs<int>(node));
        return;
      case ScalarType::Double:
        list.set(key, scalarAs<double>(node));
        return;
      case ScalarType::String:
        list.set(key, node.Scalar());
        return;
    }
  }

  // The least specific type of the scalars in `items` (bools read as strings in arrays).
  ScalarType itemsType(const std::vector<YAML::Node>& items, const std::string& path) const {
    ScalarType type = ScalarType::Int;
    for (const auto& item : items) {
      if (!item.IsScalar())
        throw InputError(where(label_, item.Mark()) + ": a list holds numbers or words here" +
                         inside(path));
      ScalarType t = scalarType(item);
      if (t == ScalarType::Bool) t = ScalarType::String;
      type = std::max(type, t);
    }
    return type;
  }

  // Calls set(T{}) with T the C++ type of an array's items of `type` (bools are ints, as
  // itemsType never gives Bool).
  template <class Set>
  static void withType(ScalarType type, Set&& set) {
    if (type == ScalarType::Double)
      set(double{});
    else if (type == ScalarType::String)
      set(std::string{});
    else
      set(int{});
  }

  template <typename T>
  static Teuchos::Array<T> array(const std::vector<YAML::Node>& items) {
    Teuchos::Array<T> out;
    for (const auto& item : items)
      out.push_back(scalarAs<T>(item));
    return out;
  }

  template <typename T>
  static Teuchos::TwoDArray<T> table(const std::vector<std::vector<YAML::Node>>& rows) {
    const auto columns = static_cast<Teuchos::Ordinal>(rows.empty() ? 0 : rows[0].size());
    Teuchos::TwoDArray<T> out(static_cast<Teuchos::Ordinal>(rows.size()), columns);
    for (std::size_t r = 0; r < rows.size(); ++r)
      for (std::size_t c = 0; c < rows[r].size(); ++c)
        out(r, c) = scalarAs<T>(rows[r][c]);
    return out;
  }

  void sequence(const YAML::Node& node, Teuchos::ParameterList& list, const std::string& key,
                const std::string& path) {
    std::vector<YAML::Node> items(node.begin(), node.end());
    countEntries(items.size());
    for (const auto& item : items)
      if (item.IsMap())
        throw InputError(where(label_, item.Mark()) + ": a list of sections is not a scene value" +
                         inside(path));
    const bool nested = !items.empty() && items.front().IsSequence();
    if (!nested) {
      withType(itemsType(items, path),
               [&](auto tag) { list.set(key, array<decltype(tag)>(items)); });
      return;
    }
    std::vector<std::vector<YAML::Node>> rows;
    std::vector<YAML::Node> all;
    for (const auto& row : items) {
      if (!row.IsSequence())
        throw InputError(where(label_, row.Mark()) + ": a table's rows are all lists" +
                         inside(path));
      rows.emplace_back(row.begin(), row.end());
      if (rows.back().size() != rows.front().size())
        throw InputError(where(label_, row.Mark()) + ": a table's rows have " +
                         std::to_string(rows.front().size()) + " items each, this one " +
                         std::to_string(rows.back().size()) + inside(path));
      all.insert(all.end(), rows.back().begin(), rows.back().end());
    }
    withType(itemsType(all, path), [&](auto tag) { list.set(key, table<decltype(tag)>(rows)); });
  }
};

// The line (1-based) of a second document's start marker, or 0: a "---" line after the first
// document's content (a marker before any content starts the first one).
int secondDocumentLine(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  int number = 0;
  bool content = false;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const bool marker = line.rfind("---", 0) == 0 && (line.size() == 3 || line[3] == ' ');
    if (marker && content) return number;
    const std::size_t first = line.find_first_not_of(' ');
    if (!marker && first != std::string::npos && line[first] != '#') content = true;
  }
  return 0;
}

}  // namespace

Teuchos::RCP<Teuchos::ParameterList> parseYamlParameterList(const std::string& text,
                                                            const std::string& label) {
  // One document: YAML::Load, not LoadAll (yaml-cpp 0.7's LoadAll loops without end, taking
  // memory, on some malformed text: a line that starts with a comma).
  if (const int line = secondDocumentLine(text))
    throw InputError(label + ": line " + std::to_string(line) +
                     ": a second YAML document ('---'); a scene is one");
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError("malformed YAML in '" + label + "' at line " +
                     std::to_string(e.mark.line + 1) + " column " +
                     std::to_string(e.mark.column + 1) + ": " + e.msg);
  }
  if (root.IsNull()) throw InputError(label + ": the file is empty");
  const std::vector<std::pair<YAML::Node, YAML::Node>> top(root.begin(), root.end());
  if (!root.IsMap() || top.empty())
    throw InputError(
        where(label, root.Mark()) +
        ": a scene is a mapping with one key, 'contactlab:', and its sections under it");
  if (top.size() > 1)
    throw InputError(where(label, top[1].first.Mark()) + ": a second top-level key ('" +
                     top[1].first.Scalar() + "'); everything goes under the first one");
  const YAML::Node& key = top[0].first;
  const YAML::Node& body = top[0].second;
  const std::string name = key.IsScalar() ? key.Scalar() : "";
  auto list = Teuchos::rcp(new Teuchos::ParameterList(name));
  Converter converter(label);
  if (body.IsMap())
    converter.mapping(body, *list, "");
  else if (!body.IsNull())
    throw InputError(where(label, body.Mark()) + ": '" + name +
                     ":' is followed by a value; a scene's sections go under it");
  return list;
}

}  // namespace contactlab
