#include "core/io/AtomicFile.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace contactlab {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  throw std::runtime_error("cannot write results to '" + path + "': " + reason);
}

}  // namespace

std::string temporaryPathFor(const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (!target.has_filename()) fail(path, "the path names a directory, not a file");
  const fs::path parent = target.parent_path();
  if (!parent.empty()) {
    // create_directories tolerates another rank creating the same directory concurrently.
    std::error_code ec;
    fs::create_directories(parent, ec);
    if (ec) fail(path, "cannot create directory '" + parent.string() + "': " + ec.message());
  }
  // Same directory as the target so that the final rename never crosses file systems; the
  // pid keeps ranks and concurrent runs from clobbering each other's temporaries.
  const std::string name = "." + target.filename().string() + ".tmp." + std::to_string(getpid());
  return (parent / name).string();
}

void commitFile(const std::string& temporary, const std::string& path) {
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int err = errno;
    discardFile(temporary);
    fail(path, std::strerror(err));
  }
}

void discardFile(const std::string& temporary) noexcept {
  std::remove(temporary.c_str());
}

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  const std::string temporary = temporaryPathFor(path);
  try {
    std::ofstream out;
    errno = 0;
    out.open(temporary, std::ios::out | std::ios::trunc | std::ios::binary);
    if (!out) fail(path, errno != 0 ? std::strerror(errno) : "cannot open a temporary file");
    write(out);
    errno = 0;
    out.close();
    // close() flushes: a full disk shows up here rather than as a silently truncated file.
    if (!out) fail(path, errno != 0 ? std::strerror(errno) : "write failed");
  } catch (...) {
    discardFile(temporary);
    throw;
  }
  commitFile(temporary, path);
}

}  // namespace contactlab
