#include "MpiTestUtils.hpp"
#include "TestMeshes.hpp"

#include "core/io/VtkSeriesWriter.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace contactlab {
namespace {

using test::commRank;
using test::commSize;

std::string readAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Files a series of `steps` steps must consist of, and nothing else (no temporaries).
std::vector<std::string> expectedFiles(const std::string& base, int steps) {
  std::vector<std::string> files{base + ".pvd"};
  for (int s = 0; s < steps; ++s) {
    char step[16];
    std::snprintf(step, sizeof step, "_%06d", s);
    if (commSize() == 1) {
      files.push_back(base + step + ".vtu");
    } else {
      files.push_back(base + step + ".pvtu");
      for (int r = 0; r < commSize(); ++r)
        files.push_back(base + step + "_p" + std::to_string(r) + ".vtu");
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// These series are read back and checked value by value by read_vtk.py (ctest unit_io.read_vtk).
void writeSeries(const std::string& name, const std::vector<ElementType>& types, int numCells,
                 int dim, const std::vector<double>& times) {
  const std::string dir = test::testOutputDir(name, commSize());
  test::freshDirectory(dir);
  VtkSeriesWriter writer(dir, name, MPI_COMM_WORLD);
  for (const double t : times)
    writer.writeStep(t, test::makeTestPiece(types, numCells, dim, commRank(), commSize(), t));
  EXPECT_EQ(writer.numSteps(), static_cast<int>(times.size()));
  MPI_Barrier(MPI_COMM_WORLD);
  EXPECT_EQ(test::listDirectory(dir), expectedFiles(name, static_cast<int>(times.size())));
  const std::string pvd = readAll(writer.pvdPath());
  EXPECT_NE(pvd.find("timestep=\"0.10000000000000001\""), std::string::npos) << pvd;
  char last[16];
  std::snprintf(last, sizeof last, "_%06d.", static_cast<int>(times.size()) - 1);
  EXPECT_NE(pvd.find("file=\"" + name + last + (commSize() > 1 ? "pvtu" : "vtu") + "\""),
            std::string::npos)
      << pvd;
}

TEST(VtkSeriesWriter, PlaneMeshThreeSteps) {
  writeSeries("plane", test::planeCellTypes(), 16, 2, {0.0, 0.1, 1.0 / 3.0});
}

TEST(VtkSeriesWriter, SolidMeshTwoSteps) {
  writeSeries("solid", test::solidCellTypes(), 10, 3, {0.0, 0.1});
}

TEST(VtkSeriesWriter, EmptyPieceOnSomeRanks) {
  // One cell in all: on 2 ranks, rank 1 has an empty piece but the same fields.
  writeSeries("single", test::solidCellTypes(), 1, 3, {0.5, 0.1});
}

TEST(VtkSeriesWriter, InvalidPieceOnOneRankThrowsOnEveryRank) {
  const std::string dir = test::testOutputDir("invalid", commSize());
  test::freshDirectory(dir);
  VtkSeriesWriter writer(dir, "result", MPI_COMM_WORLD);
  auto piece = test::makeTestPiece(test::planeCellTypes(), 8, 2, commRank(), commSize(), 0.0);
  writer.writeStep(0.0, piece);
  if (commRank() == commSize() - 1) piece.pointData[0].values.pop_back();
  try {
    writer.writeStep(1.0, piece);
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cannot write results to '"), std::string::npos) << what;
    EXPECT_NE(what.find("point field 'displacement'"), std::string::npos) << what;
  }
  EXPECT_EQ(writer.numSteps(), 1);
  MPI_Barrier(MPI_COMM_WORLD);
  EXPECT_EQ(test::listDirectory(dir), expectedFiles("result", 1));
  EXPECT_THROW(writer.writeStep(std::numeric_limits<double>::quiet_NaN(), piece),
               std::runtime_error);
}

TEST(VtkSeriesWriter, DifferentFieldsOnRanksThrow) {
  if (commSize() == 1) GTEST_SKIP() << "needs several ranks";
  const std::string dir = test::testOutputDir("mismatch", commSize());
  test::freshDirectory(dir);
  VtkSeriesWriter writer(dir, "result", MPI_COMM_WORLD);
  auto piece = test::makeTestPiece(test::planeCellTypes(), 8, 2, commRank(), commSize(), 0.0);
  if (commRank() == 1) piece.cellData.pop_back();
  EXPECT_THROW(writer.writeStep(0.0, piece), std::runtime_error);
  MPI_Barrier(MPI_COMM_WORLD);
  EXPECT_TRUE(test::listDirectory(dir).empty());
}

TEST(VtkSeriesWriter, UnwritableDirectoryThrowsOnEveryRank) {
  const std::string dir = test::testOutputDir("unwritable", commSize());
  test::freshDirectory(dir);
  if (commRank() == 0) std::ofstream(dir + "_blocker") << "a file, not a folder";
  MPI_Barrier(MPI_COMM_WORLD);
  VtkSeriesWriter writer(dir + "_blocker/out", "result", MPI_COMM_WORLD);
  const auto piece = test::makeTestPiece(test::planeCellTypes(), 4, 2, commRank(), commSize(), 0);
  try {
    writer.writeStep(0.0, piece);
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write results to '" + dir + "_blocker/out/"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(writer.numSteps(), 0);
}

}  // namespace
}  // namespace contactlab
