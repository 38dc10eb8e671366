#include "core/io/OutputFolder.hpp"

#include "base/InputError.hpp"
#include "core/io/OutputManifest.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <regex>
#include <set>
#include <system_error>
#include <unistd.h>

namespace contactlab {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const std::string& path, const std::string& reason) {
  throw InputError("cannot write results to the output folder '" + path + "': " + reason);
}

// AtomicFile's temporary of `name` (".<name>.tmp.<pid>"); empty when `file` is none.
std::string temporaryOf(const std::string& file) {
  static const std::regex pattern(R"(\.(.+)\.tmp\.\d+)");
  std::smatch match;
  return std::regex_match(file, match, pattern) ? match[1].str() : std::string();
}

// What a run writes (RunOutputs, VtkSeriesWriter, ProfileCsv): what an earlier run's folder
// without a manifest (written before runs kept one) may lose.
bool isRunOutput(const std::string& name) {
  static const std::regex pattern(
      R"(result\.pvd|result_\d+(_p\d+)?\.(vtu|pvtu)|steps\.csv|contact(_t[^/]+)?\.csv)"
      R"(|profile_[^/]+\.csv|summary\.json|checkpoint\.h5|progress\.log)");
  return std::regex_match(name, pattern);
}

// The earlier run's files a new run may remove: those its manifest lists, else (an older
// folder) those named as a run's outputs; and their temporaries.
std::function<bool(const std::string&)> earlierRunFiles(const std::string& path) {
  const std::optional<std::vector<std::string>> listed = OutputManifest::read(path);
  if (!listed)
    return
        [](const std::string& name) { return isRunOutput(name) || isRunOutput(temporaryOf(name)); };
  std::set<std::string> names(listed->begin(), listed->end());
  names.insert(OutputManifest::kFileName);
  return [names](const std::string& name) {
    return names.count(name) > 0 || names.count(temporaryOf(name)) > 0;
  };
}

// Removes the files (never a folder) in folder `path` that `which` accepts; returns their
// names.
std::vector<std::string> removeFiles(const std::string& path,
                                     const std::function<bool(const std::string&)>& which) {
  std::vector<std::string> removed;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(path), ec)) {
    const std::string name = entry.path().filename().string();
    std::error_code typeError;
    if (!which(name) || entry.is_directory(typeError)) continue;
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

void requirePlainName(const std::string& value, const std::string& key, const std::string& use) {
  const bool blank = value.find_first_not_of(" \t") == std::string::npos;
  const bool control = std::any_of(value.begin(), value.end(),
                                   [](char c) { return static_cast<unsigned char>(c) < 0x20; });
  if (blank)
    throw InputError(key + " is empty, and it names " + use + ": give a name such as 'hertz-2d'");
  if (value == "." || value.find('/') != std::string::npos ||
      value.find("..") != std::string::npos || control)
    throw InputError(key + " '" + value + "' cannot name " + use +
                     ": give a plain name, not '.' and without '/', '..' or control characters "
                     "(such as 'hertz-2d')");
}

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
  std::vector<std::string> removed = removeFiles(path, earlierRunFiles(path));
  const auto own = std::find(removed.begin(), removed.end(), OutputManifest::kFileName);
  if (own != removed.end()) removed.erase(own);
  try {
    OutputManifest::write(path, {});
  } catch (const std::runtime_error& e) {
    refuse(path, e.what());
  }
  return removed;
}

std::vector<std::string> prepareContinuedFolder(const std::string& path) {
  const bool listed = OutputManifest::read(path).has_value();
  const auto which = earlierRunFiles(path);
  const std::vector<std::string> removed =
      removeFiles(path, [&](const std::string& name) { return which(temporaryOf(name)); });
  if (listed) return removed;
  // A folder of a run from before manifests: the list starts with its run's files.
  std::vector<std::string> names;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(path), ec))
    if (isRunOutput(entry.path().filename().string()))
      names.push_back(entry.path().filename().string());
  try {
    OutputManifest::write(path, names);
  } catch (const std::runtime_error& e) {
    refuse(path, e.what());
  }
  return removed;
}

}  // namespace contactlab
