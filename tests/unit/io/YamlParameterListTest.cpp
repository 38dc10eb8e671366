// The scene reader (yaml-cpp, core/io/YamlParameterList): every shipped scene reads to the
// same typed ParameterList as Teuchos' YAML reader gave (the reader it replaced, kept here as
// the oracle), and the YAML that reader refused or mangled is read right.
#include "base/InputError.hpp"
#include "core/io/YamlParameterList.hpp"

#include <Teuchos_TwoDArray.hpp>
#include <Teuchos_YamlParameterListHelpers.hpp>

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace contactlab {
namespace {

std::string fileText(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Equal names, types and values, recursively, in the same order.
void expectSameList(const Teuchos::ParameterList& a, const Teuchos::ParameterList& b,
                    const std::string& where) {
  ASSERT_EQ(a.numParams(), b.numParams()) << where;
  auto ib = b.begin();
  for (auto ia = a.begin(); ia != a.end(); ++ia, ++ib) {
    const std::string key = where + "/" + a.name(ia);
    ASSERT_EQ(a.name(ia), b.name(ib)) << where;
    const auto& ea = a.entry(ia);
    const auto& eb = b.entry(ib);
    ASSERT_EQ(ea.isList(), eb.isList()) << key;
    if (ea.isList()) {
      expectSameList(Teuchos::getValue<Teuchos::ParameterList>(ea),
                     Teuchos::getValue<Teuchos::ParameterList>(eb), key);
      continue;
    }
    EXPECT_EQ(ea.getAny(false).typeName(), eb.getAny(false).typeName()) << key;
    EXPECT_TRUE(ea.getAny(false) == eb.getAny(false)) << key;
  }
}

TEST(YamlParameterList, EveryShippedSceneReadsAsTeuchosReadIt) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(CONTACTLAB_SCENES_DIR)) {
    if (entry.path().extension() != ".yaml") continue;
    const std::string text = fileText(entry.path());
    auto ours = parseYamlParameterList(text, entry.path().string());
    auto teuchos = Teuchos::getParametersFromYamlString(text);
    EXPECT_EQ(ours->name(), teuchos->name());
    expectSameList(*ours, *teuchos, entry.path().filename().string());
    ++scenes;
  }
  EXPECT_GT(scenes, 40);
}

TEST(YamlParameterList, TypesAsTeuchosTypesThem) {
  auto p = parseYamlParameterList(
      "contactlab:\n"
      "  i: 3\n  d: 2.5e-3\n  b: true\n  B: No\n  s: hello world\n"
      "  q: \"7\"\n  ints: [1, 2]\n  mixed: [1, 2.5]\n"
      "  words: [a, 1]\n  table: [[1, 2], [3, 4.5]]\n  empty:\n",
      "t.yaml");
  EXPECT_EQ(p->name(), "contactlab");
  EXPECT_EQ(p->get<int>("i"), 3);
  EXPECT_DOUBLE_EQ(p->get<double>("d"), 2.5e-3);
  EXPECT_TRUE(p->get<bool>("b"));
  EXPECT_FALSE(p->get<bool>("B"));
  EXPECT_EQ(p->get<std::string>("s"), "hello world");
  EXPECT_EQ(p->get<std::string>("q"), "7");
  EXPECT_EQ(p->get<Teuchos::Array<int>>("ints"), Teuchos::Array<int>(std::vector<int>{1, 2}));
  EXPECT_EQ(p->get<Teuchos::Array<double>>("mixed"),
            Teuchos::Array<double>(std::vector<double>{1.0, 2.5}));
  EXPECT_EQ(p->get<Teuchos::Array<std::string>>("words"),
            Teuchos::Array<std::string>(std::vector<std::string>{"a", "1"}));
  const auto table = p->get<Teuchos::TwoDArray<double>>("table");
  EXPECT_EQ(table.getNumRows(), 2);
  EXPECT_DOUBLE_EQ(table(1, 1), 4.5);
  EXPECT_TRUE(p->isSublist("empty"));
}

// What Teuchos' reader refused or mangled.
TEST(YamlParameterList, ReadsValidYamlTheOldReaderRefused) {
  // An indentless block sequence (PyYAML's default output).
  auto p = parseYamlParameterList("contactlab:\n  Times:\n  - 0.0\n  - 0.5\n", "t.yaml");
  EXPECT_EQ(p->get<Teuchos::Array<double>>("Times"),
            Teuchos::Array<double>(std::vector<double>{0.0, 0.5}));
  // Non-ASCII text in comments and values, and a UTF-8 byte-order mark.
  p = parseYamlParameterList(
      "\xEF\xBB\xBF# \xCE\xBC = 0.3\ncontactlab:\n  Note: 304 \xC2\xB0"
      "C\n",
      "t.yaml");
  EXPECT_EQ(p->get<std::string>("Note"),
            "304 \xC2\xB0"
            "C");
  // Escapes in double quotes.
  p = parseYamlParameterList("contactlab:\n  s: \"tab\\there\"\n", "t.yaml");
  EXPECT_EQ(p->get<std::string>("s"), "tab\there");
}

void expectRefused(const std::string& text, const std::vector<std::string>& words) {
  try {
    parseYamlParameterList(text, "t.yaml");
    ADD_FAILURE() << "accepted:\n" << text;
  } catch (const InputError& e) {
    for (const auto& w : words)
      EXPECT_NE(std::string(e.what()).find(w), std::string::npos) << e.what() << " | " << w;
  }
}

TEST(YamlParameterList, RefusesWithLineAndKeyPath) {
  expectRefused("contactlab:\n  a: 1\nother:\n  b: 2\n", {"t.yaml", "line 3", "second top-level"});
  expectRefused("contactlab:\n  S:\n    a: 1\n    a: 2\n",
                {"line 4", "'a'", "given twice", "first at line 3", "'S'"});
  expectRefused("contactlab:\n  L:\n    - {a: 1}\n", {"line 3", "list of sections", "'L'"});
  expectRefused("contactlab:\n  a: [1, 2\n", {"malformed YAML", "t.yaml", "line"});
  expectRefused("contactlab:\n  T: [[1, 2], [3]]\n", {"table", "'T'"});
  expectRefused("", {"empty"});
  expectRefused("contactlab: 3\n", {"followed by a value"});
  expectRefused("contactlab:\n  a: 1\n---\ncontactlab:\n  a: 2\n", {"second YAML document"});
}

}  // namespace
}  // namespace contactlab
