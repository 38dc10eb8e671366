// Every MUMPS entry point a process calls comes from one build: the one contactlab_linear was
// linked with (Debian's libmumps-ptscotch, SCOTCH orderings), not the PORD-only libmumps that
// Trilinos' libraries also load. The search order decides, and it is this binary's (it loads
// contactlab_algorithms, whose NOX dependency brought the PORD-only libsmumps in first:
// `smumps_c` bound to it, and single-precision factors lost SCOTCH; algorithms/CMakeLists.txt).
#include "linear/MumpsSolver.hpp"

#include <dlfcn.h>
#include <gtest/gtest.h>
#include <string>

namespace contactlab {
namespace {

// The file of the library that the process's global search order resolves `symbol` to.
std::string libraryOf(const char* symbol) {
  void* address = dlsym(RTLD_DEFAULT, symbol);
  Dl_info info{};
  if (!address || !dladdr(address, &info) || !info.dli_fname) return {};
  return info.dli_fname;
}

TEST(MumpsBuild, SingleAndDoubleEntryPointsComeFromTheLinkedBuild) {
  const std::string dbl = libraryOf("dmumps_c"), sgl = libraryOf("smumps_c");
  ASSERT_FALSE(dbl.empty());
  ASSERT_FALSE(sgl.empty());
  const bool scotch = MumpsSolver::hasScotch();
  EXPECT_EQ(dbl.find("ptscotch") != std::string::npos, scotch) << dbl;
  EXPECT_EQ(sgl.find("ptscotch") != std::string::npos, scotch) << sgl;
  // The common part too (orderings' wrappers, out-of-core state): one of it, the same build's.
  const std::string common = libraryOf("mumps_pord");
  EXPECT_EQ(common.find("ptscotch") != std::string::npos, scotch) << common;
}

}  // namespace
}  // namespace contactlab
