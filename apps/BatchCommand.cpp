#include "apps/BatchCommand.hpp"

#include "apps/CommandErrors.hpp"
#include "apps/LinearSolverPool.hpp"
#include "apps/MeshCache.hpp"
#include "apps/RunCommand.hpp"

#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace contactlab {
namespace {

std::vector<std::string> tabFields(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, '\t'))
    fields.push_back(field);
  if (!line.empty() && line.back() == '\t') fields.emplace_back();
  return fields;
}

void flushAll() {
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
}

// Each run reports its own peak memory (summary.json): the process's high-water mark starts
// again from what is resident now (Linux >= 4.0; elsewhere the peak stays the process's).
void resetPeakMemory() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
}

// Stdout and stderr into `path` while a run writes, then back (the answers go to stdout).
class OutputRedirection {
 public:
  explicit OutputRedirection(const std::string& path) {
    log_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (log_ < 0) return;
    flushAll();
    out_ = ::dup(STDOUT_FILENO);
    err_ = ::dup(STDERR_FILENO);
    ::dup2(log_, STDOUT_FILENO);
    ::dup2(log_, STDERR_FILENO);
  }
  OutputRedirection(const OutputRedirection&) = delete;
  OutputRedirection& operator=(const OutputRedirection&) = delete;
  ~OutputRedirection() {
    if (log_ < 0) return;
    flushAll();
    ::dup2(out_, STDOUT_FILENO);
    ::dup2(err_, STDERR_FILENO);
    ::close(out_);
    ::close(err_);
    ::close(log_);
  }
  bool opened() const { return log_ >= 0; }

 private:
  int log_ = -1, out_ = -1, err_ = -1;
};

// One request: its exit code (2 for a request the batch cannot run, said on stderr).
int runRequest(const std::vector<std::string>& fields, const Teuchos::RCP<const Comm>& comm,
               bool quiet, LinearSolverPool& solvers, MeshCache& meshes) {
  if (fields.size() < 2 || fields[0].empty()) {
    std::cerr << "contactlab: error: batch: a line is OUT<tab>SCENE[<tab>key=value ...], with "
                 "OUT not empty\n";
    return 2;
  }
  SimulationOptions options;
  options.outputDirectory = fields[0];
  options.scenePath = fields[1];
  options.overrides.assign(fields.begin() + 2, fields.end());
  options.quiet = quiet;
  options.solverPool = &solvers;
  options.meshCache = &meshes;
  std::error_code ec;
  std::filesystem::create_directories(options.outputDirectory, ec);
  const std::string log = options.outputDirectory + "/run.log";
  OutputRedirection redirection(log);
  if (!redirection.opened()) {
    std::cerr << "contactlab: error: batch: cannot write " << log << ": " << std::strerror(errno)
              << "\n";
    return 2;
  }
  resetPeakMemory();
  return withErrorsReported(*comm, [&] { return runCommand(options, comm); });
}

}  // namespace

int batchCommand(const Teuchos::RCP<const Comm>& comm, bool quiet) {
  if (comm->getSize() > 1) {
    if (comm->getRank() == 0)
      std::cerr << "contactlab: error: batch runs on one rank (its runs are the study's "
                   "single-rank processes); start it without mpirun\n";
    return 2;
  }
  LinearSolverPool solvers;
  MeshCache meshes;
  for (std::string line; std::getline(std::cin, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const int code = runRequest(tabFields(line), comm, quiet, solvers, meshes);
    std::cout << "exit " << code << std::endl;
    if (code >= 128) return code;  // interrupted: the batch stops with the run
  }
  return 0;
}

}  // namespace contactlab
