#include "apps/MpiSessionDirectory.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <vector>

namespace contactlab {

MpiSessionDirectory::MpiSessionDirectory() {
  if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr) return;
  if (std::getenv("OMPI_MCA_orte_tmpdir_base") != nullptr) return;
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = (tmp != nullptr && *tmp != '\0' ? std::string(tmp) : "/tmp");
  pattern += "/contactlab-mpi-XXXXXX";
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  // Without a directory of its own the process still runs, as before, in the shared one.
  if (mkdtemp(buffer.data()) == nullptr) return;
  path_ = buffer.data();
  setenv("OMPI_MCA_orte_tmpdir_base", path_.c_str(), 1);
}

MpiSessionDirectory::~MpiSessionDirectory() {
  if (path_.empty()) return;
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace contactlab
