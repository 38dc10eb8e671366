#include "core/io/OutputFolder.hpp"

#include "base/InputError.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <system_error>
#include <unistd.h>

namespace contactlab {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const std::string& path, const std::string& reason) {
  throw InputError("cannot write results to the output folder '" + path + "': " + reason);
}

// AtomicFile's temporaries.
bool isTemporary(const std::string& name) {
  static const std::regex pattern(R"(\..+\.tmp\.\d+)");
  return std::regex_match(name, pattern);
}

// What a run writes (RunCommand, VtkSeriesWriter, AtomicFile's temporaries).
bool isRunOutput(const std::string& name) {
  static const std::regex pattern(
      R"(result\.pvd|result_\d+(_p\d+)?\.(vtu|pvtu)|steps\.csv|contact(_t[^/]+)?\.csv)"
      R"(|summary\.json|checkpoint\.h5|progress\.log)");
  return std::regex_match(name, pattern) || isTemporary(name);
}

// Removes the files in folder `path` that `which` accepts; returns their names.
template <class Which>
std::vector<std::string> removeFiles(const std::string& path, Which which) {
  std::vector<std::string> removed;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(path), ec)) {
    const std::string name = entry.path().filename().string();
    if (!which(name) || entry.is_directory()) continue;
    std::error_code removeError;
    fs::remove(entry.path(), removeError);
    if (removeError)
      refuse(path, "cannot remove an earlier run's '" + name + "': " + removeError.message());
    removed.push_back(name);
  }
  if (ec) refuse(path, "cannot list it: " + ec.message());
  return removed;
}

// The first existing ancestor of `path` that is not a directory, if any.
std::string fileInTheWay(const fs::path& path) {
  for (fs::path p = path; !p.empty(); p = p.parent_path()) {
    std::error_code ec;
    const fs::file_status s = fs::status(p, ec);
    if (!ec && fs::exists(s)) return fs::is_directory(s) ? std::string() : p.string();
    if (p == p.parent_path()) break;
  }
  return {};
}

}  // namespace

std::vector<std::string> prepareOutputFolder(const std::string& path) {
  if (path.empty()) refuse(path, "the path is empty");
  const fs::path folder(path);
  const std::string file = fileInTheWay(folder);
  if (!file.empty())
    refuse(path, file == folder.string() ? "it is a file, not a folder"
                                         : "'" + file + "' is a file, not a folder");
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) refuse(path, "cannot create it: " + ec.message());
  // Permissions alone do not tell (root, read-only mounts): write a probe file.
  const fs::path probe = folder / (".contactlab-probe." + std::to_string(getpid()));
  {
    errno = 0;
    std::ofstream out(probe);
    if (!out) refuse(path, errno ? std::strerror(errno) : "cannot create a file in it");
  }
  fs::remove(probe, ec);
  return removeFiles(path, isRunOutput);
}

std::vector<std::string> removeTemporaries(const std::string& path) {
  return removeFiles(path, isTemporary);
}

}  // namespace contactlab
