#include "core/io/OutputManifest.hpp"

#include "core/io/AtomicFile.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>
#include <utility>

namespace contactlab {
namespace {

std::string manifestPath(const std::string& folder) {
  return folder + "/" + OutputManifest::kFileName;
}

// One whole line, by one write(2) in append mode.
void appendLine(const std::string& path, const std::string& line) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error("cannot write results to '" + path + "': " + std::strerror(errno));
  const std::string text = line + "\n";
  const ssize_t written = ::write(fd, text.data(), text.size());
  const int error = errno;
  ::close(fd);
  if (written != static_cast<ssize_t>(text.size()))
    throw std::runtime_error("cannot write results to '" + path +
                             "': " + (written < 0 ? std::strerror(error) : "short write"));
}

}  // namespace

bool isPlainFileName(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos &&
         name.find('\0') == std::string::npos;
}

OutputManifest::OutputManifest(std::string folder, bool record)
    : folder_(std::move(folder)), record_(record) {
  if (!record_) return;
  if (const auto names = read(folder_)) listed_.insert(names->begin(), names->end());
}

std::string OutputManifest::path(const std::string& name) {
  add({name});
  return folder_ + "/" + name;
}

void OutputManifest::add(const std::vector<std::string>& names) {
  if (!record_) return;
  for (const std::string& name : names) {
    if (listed_.count(name)) continue;
    if (!isPlainFileName(name) || name.find('\n') != std::string::npos)
      throw std::logic_error("OutputManifest: '" + name + "' is not a plain file name");
    appendLine(manifestPath(folder_), name);
    listed_.insert(name);
  }
}

std::optional<std::vector<std::string>> OutputManifest::read(const std::string& folder) {
  std::ifstream in(manifestPath(folder), std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  std::vector<std::string> names;
  std::string all = text.str(), line;
  // Lines end in '\n': an unfinished last line (a crash mid-append) is not a name.
  for (std::size_t start = 0, end; (end = all.find('\n', start)) != std::string::npos;
       start = end + 1) {
    line = all.substr(start, end - start);
    if (isPlainFileName(line)) names.push_back(line);
  }
  return names;
}

void OutputManifest::write(const std::string& folder, const std::vector<std::string>& names) {
  writeFileAtomically(manifestPath(folder), [&](std::ostream& out) {
    for (const std::string& name : names)
      out << name << "\n";
  });
}

}  // namespace contactlab
