#pragma once
// A private Open MPI session directory for a contactlab started without mpirun.
//
// Started alone, contactlab is an isolated MPI singleton (main.cpp). Every isolated singleton
// is job family 0, so all of them share one session directory, <tmp>/ompi.<host>.<uid>/jf.0:
// one process ending removes it while another is creating its own part of it, and that one
// aborts in MPI_Init ("A call to mkdir was unable to create the desired directory"). Two runs
// of a study, ctest -j2 or a user's script started them together.
//
// Constructed before MPI_Init, this object makes a fresh directory (mkdtemp under TMPDIR, or
// /tmp) and points Open MPI's session directories there (OMPI_MCA_orte_tmpdir_base), so no two
// processes share one; destroyed after MPI_Finalize, it removes the directory. It does nothing
// under mpirun (the launcher owns the session) or when the user set the variable.
#include <string>

namespace contactlab {

class MpiSessionDirectory {
 public:
  MpiSessionDirectory();
  ~MpiSessionDirectory();
  MpiSessionDirectory(const MpiSessionDirectory&) = delete;
  MpiSessionDirectory& operator=(const MpiSessionDirectory&) = delete;

  // The directory made, or empty when none was (mpirun, a user's setting, mkdtemp failed).
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace contactlab
