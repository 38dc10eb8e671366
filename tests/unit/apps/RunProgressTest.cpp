// RunProgress's iterate lines (apps/RunProgress.hpp), read back from its progress log: an
// iterate below the step's target that Newton does not stop at says what it waits for.
#include "apps/RunProgress.hpp"

#include <cstdio>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <unistd.h>

namespace contactlab {
namespace {

std::string logged(const StaticSolver::IterateProgress& p) {
  const std::string path =
      ::testing::TempDir() + "run_progress_" + std::to_string(::getpid()) + ".log";
  {
    RunProgress progress(false, 1.0, path);
    progress.iteration(p, 1.0);
  }
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::remove(path.c_str());
  return text.str();
}

StaticSolver::IterateProgress iterate(double residual, int statusChanges, double contact) {
  StaticSolver::IterateProgress p;
  p.step = 1;
  p.time = 1;
  p.iteration = 9;
  p.residual = residual;
  p.target = 3e-6;
  p.statusChanges = statusChanges;
  p.contactResidual = contact;
  return p;
}

TEST(RunProgress, AnIterateBelowTheTargetSaysWhatNewtonWaitsFor) {
  EXPECT_NE(logged(iterate(2.2e-6, 2, 0))
                .find("below the target 3.0e-06; 2 contact status(es) "
                      "changed"),
            std::string::npos);
  EXPECT_NE(logged(iterate(2.2e-6, 0, 5e-6))
                .find("below the target 3.0e-06; contact rows "
                      "5.0e-06 above it"),
            std::string::npos);
  // Above the target, or settled: no such note.
  EXPECT_EQ(logged(iterate(4e-6, 2, 0)).find("below the target"), std::string::npos);
  EXPECT_EQ(logged(iterate(2.2e-6, 0, 1e-6)).find("below the target"), std::string::npos);
}

}  // namespace
}  // namespace contactlab
