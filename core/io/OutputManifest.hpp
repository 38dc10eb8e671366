#pragma once
// The list of the files a run writes into its output folder, kept in that folder as
// `.contactlab-outputs` (one file name a line). A name is listed before its file is first
// written, so the list holds every file of a run killed at any point; the next run in the
// folder removes what the list names and nothing else (prepareOutputFolder).
//
// prepareOutputFolder starts the list (an empty file, written atomically); it then grows by
// one whole line at a time, appended by a single write(2) on an O_APPEND descriptor: a crash
// leaves at most an unfinished last line, which read() ignores.
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace contactlab {

class OutputManifest {
 public:
  static constexpr const char* kFileName = ".contactlab-outputs";

  // The manifest of `folder`, with what it lists already (a continued run adds to it).
  // `record` false (ranks other than 0, which write only the pieces rank 0 lists): nothing is
  // read or written, path() only joins.
  OutputManifest(std::string folder, bool record);

  // The path of `name` in the folder, `name` listed first when it is new. Throws
  // std::runtime_error "cannot write results to ..." when the manifest cannot be written.
  std::string path(const std::string& name);
  // Lists the names that are new.
  void add(const std::vector<std::string>& names);

  const std::string& folder() const { return folder_; }

  // The plain file names (no '/', not '.' or '..') the manifest of `folder` lists; nullopt
  // when the folder has no manifest.
  static std::optional<std::vector<std::string>> read(const std::string& folder);
  // Starts the manifest of `folder` with `names` (written atomically).
  static void write(const std::string& folder, const std::vector<std::string>& names);

 private:
  std::string folder_;
  bool record_;
  std::set<std::string> listed_;
};

// Whether `name` can be a file of a folder: not empty, no '/', not '.' or '..'.
bool isPlainFileName(const std::string& name);

}  // namespace contactlab
