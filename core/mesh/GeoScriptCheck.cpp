#include "core/mesh/GeoScriptCheck.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace contactlab {
namespace {

namespace fs = std::filesystem;

struct Token {
  enum Kind { name, text, punctuation, other } kind;
  std::string value;
  int line;
};

// gmsh's lexer (Parser/Gmsh.l), as far as the check needs it: comments, strings (between " or
// ', without escapes), names, ">>", one character otherwise.
std::vector<Token> tokens(const std::string& s) {
  std::vector<Token> out;
  int line = 1;
  const auto countLines = [&](std::size_t from, std::size_t to) {
    line +=
        static_cast<int>(std::count(s.begin() + from, s.begin() + std::min(to, s.size()), '\n'));
  };
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (s.compare(i, 2, "//") == 0) {
      i = s.find('\n', i);
      if (i == std::string::npos) i = s.size();
    } else if (s.compare(i, 2, "/*") == 0) {
      std::size_t end = s.find("*/", i + 2);
      end = end == std::string::npos ? s.size() : end + 2;
      countLines(i, end);
      i = end;
    } else if (c == '"' || c == '\'') {
      std::size_t end = s.find(c, i + 1);
      if (end == std::string::npos) end = s.size();
      out.push_back({Token::text, s.substr(i + 1, end - i - 1), line});
      countLines(i, end);
      i = end + 1;
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t end = i;
      while (end < s.size() && (std::isalnum(static_cast<unsigned char>(s[end])) || s[end] == '_'))
        ++end;
      out.push_back({Token::name, s.substr(i, end - i), line});
      i = end;
    } else if (s.compare(i, 2, ">>") == 0) {
      out.push_back({Token::punctuation, ">>", line});
      i += 2;
    } else if (std::ispunct(static_cast<unsigned char>(c))) {
      out.push_back({Token::punctuation, std::string(1, c), line});
      ++i;
    } else {
      out.push_back({Token::other, std::string(1, c), line});
      ++i;
    }
  }
  return out;
}

// The commands that reach outside the model, and what they do.
const std::map<std::string, std::string>& outsideCommands() {
  static const std::map<std::string, std::string> commands{
      {"System", "runs a program"},
      {"SystemCall", "runs a program"},
      {"NonBlockingSystemCall", "runs a program"},
      {"OnelabRun", "runs a program"},
      {"SendToServer", "talks to another program"},
      {"CreateDir", "creates a folder"},
      {"Save", "writes a file"},
      {"Print", "writes a file"},
      {"Exit", "ends the process"}};
  return commands;
}

// Files gmsh reads as data, not as scripts (by extension, as gmsh's Merge decides).
bool isDataFile(const fs::path& file) {
  static const std::set<std::string> data{
      ".msh",  ".stl",  ".brep", ".brp", ".step", ".stp", ".iges", ".igs", ".med",
      ".mmed", ".rmed", ".unv",  ".vtk", ".mesh", ".bdf", ".nas",  ".p3d", ".ply2",
      ".ply",  ".off",  ".cgns", ".inp", ".x3d",  ".neu", ".xyz"};
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return data.count(extension) > 0;
}

class ScriptChecker {
 public:
  void check(const fs::path& file, int depth) {
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(file, ec);
    if (!visited_.insert(ec ? file.string() : canonical.string()).second || depth > 32) return;
    std::ifstream in(file, std::ios::binary);
    if (!in) return;  // gmsh says that it cannot open it
    std::stringstream text;
    text << in.rdbuf();
    const std::vector<Token> t = tokens(text.str());
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t[i].kind != Token::name) continue;
      const bool option = (i > 0 && t[i - 1].value == ".") ||
                          (i + 1 < t.size() && t[i + 1].value == ".");  // General.X, Print.X
      const std::string& word = t[i].value;
      const auto command = outsideCommands().find(word);
      if (command != outsideCommands().end() && !option) refuse(file, t[i], command->second);
      if (word == "Printf" && redirected(t, i)) refuse(file, t[i], "writes a file (> or >>)");
      if (i > 0 && t[i - 1].value == "." && word.size() > 8 &&
          word.compare(word.size() - 8, 8, "FileName") == 0 && i + 1 < t.size() &&
          t[i + 1].value == "=")
        refuse(file, t[i], "names a file gmsh writes");
      if (word == "Include" || word == "Merge" || word == "MergeWithBoundingBox" ||
          word == "Open") {
        if (option) continue;
        if (i + 1 >= t.size() || t[i + 1].kind != Token::text)
          refuse(file, t[i],
                 "takes a computed path, which contactlab cannot check before gmsh runs it "
                 "(write the path as a quoted string)");
        fs::path target = t[i + 1].value;
        if (target.is_relative()) target = file.parent_path() / target;
        if (word == "Include" || !isDataFile(target)) check(target, depth + 1);
      }
    }
  }

 private:
  // Printf(...) > "file" or >> "file".
  static bool redirected(const std::vector<Token>& t, std::size_t i) {
    std::size_t j = i + 1;
    if (j >= t.size() || t[j].value != "(") return false;
    for (int open = 0; j < t.size(); ++j) {
      if (t[j].kind != Token::punctuation) continue;
      if (t[j].value == "(") ++open;
      if (t[j].value == ")" && --open == 0) break;
    }
    return j + 1 < t.size() && (t[j + 1].value == ">" || t[j + 1].value == ">>");
  }

  [[noreturn]] static void refuse(const fs::path& file, const Token& token,
                                  const std::string& what) {
    throw std::invalid_argument(
        "mesh file '" + file.lexically_normal().string() + "', line " + std::to_string(token.line) +
        ": '" + token.value + "' " + what +
        "; contactlab meshes scripts that build a geometry and its mesh and write nothing "
        "(remove the command, or mesh the script with gmsh and give the .msh)");
  }

  std::set<std::string> visited_;
};

}  // namespace

void checkGeoScript(const std::string& path) {
  ScriptChecker().check(fs::path(path), 0);
}

}  // namespace contactlab
