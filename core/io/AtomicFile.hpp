#pragma once
// Crash-safe file output: every result file is written under a temporary name in its own
// directory and renamed into place, so readers (ParaView, scripts, a restarted run) only ever
// see complete files and the last committed version survives a crash mid-write.
#include <functional>
#include <ostream>
#include <string>

namespace contactlab {

// Writes `path` through `write` into a temporary file, then renames it onto `path`. Parent
// directories are created. If `write` throws, the temporary is removed, `path` keeps its old
// content (if any) and the exception propagates. I/O errors throw std::runtime_error
// "cannot write results to '<path>': <reason>".
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// For writers that need a file name (e.g. VTK's): returns "<dir>/.<name>.tmp.<pid>" next to
// `path`, after creating the parent directories. Pair with commitFile or discardFile.
std::string temporaryPathFor(const std::string& path);

// Renames `temporary` onto `path` (atomic on POSIX within one file system). On failure the
// temporary is removed and std::runtime_error names `path`.
void commitFile(const std::string& temporary, const std::string& path);

// Removes `temporary` if it exists; never throws (used on error paths).
void discardFile(const std::string& temporary) noexcept;

}  // namespace contactlab
