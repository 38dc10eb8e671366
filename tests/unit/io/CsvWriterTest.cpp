#include "MpiTestUtils.hpp"
#include "TestMeshes.hpp"

#include "core/io/CsvWriter.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace contactlab {
namespace {

TEST(CsvWriter, HeaderAndMixedRows) {
  CsvWriter csv({"step", "time", "status", "residual"});
  csv.addRow(1, 0.5, "slip", 1e-12);
  csv.addRow(std::int64_t{2}, 1.0, std::string("stick"), 0.0);
  EXPECT_EQ(csv.numRows(), 2u);
  EXPECT_EQ(csv.str(),
            "step,time,status,residual\n"
            "1,0.5,slip,9.9999999999999998e-13\n"
            "2,1,stick,0\n");
}

TEST(CsvWriter, FullPrecisionRoundTrips) {
  for (const double v : {0.1, 1.0 / 3.0, -2.5e-300, 6.02214076e23, 1.0 + 1e-15}) {
    const std::string text = CsvWriter::format(v);
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), v) << text;
  }
  EXPECT_EQ(CsvWriter::format(0.1), "0.10000000000000001");
}

TEST(CsvWriter, NonFiniteValues) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(CsvWriter::format(nan), "");  // not defined: an empty cell, never "nan"
  EXPECT_EQ(CsvWriter::format(-nan), "");
  EXPECT_EQ(CsvWriter::format(inf), "inf");
  EXPECT_EQ(CsvWriter::format(-inf), "-inf");
  CsvWriter csv({"a", "b"});
  csv.addRow(std::vector<double>{nan, 2.0});
  EXPECT_EQ(csv.str(), "a,b\n,2\n");
}

TEST(CsvWriter, QuotesOnlyWhenNeeded) {
  CsvWriter csv({"name", "note"});
  csv.addRow("plain", "a,b");
  csv.addRow("say \"hi\"", "two\nlines");
  EXPECT_EQ(csv.str(),
            "name,note\n"
            "plain,\"a,b\"\n"
            "\"say \"\"hi\"\"\",\"two\nlines\"\n");
}

TEST(CsvWriter, RejectsRowOfWrongLength) {
  CsvWriter csv({"a", "b"});
  EXPECT_THROW(csv.addRow(1), std::invalid_argument);
  EXPECT_THROW(csv.addRow(std::vector<double>{1, 2, 3}), std::invalid_argument);
  EXPECT_EQ(csv.numRows(), 0u);
  EXPECT_THROW(CsvWriter({}), std::invalid_argument);
}

TEST(CsvWriter, WriteRewritesWholeFileAtomically) {
  const std::string dir =
      test::testOutputDir("csv", test::commSize()) + "/rank" + std::to_string(test::commRank());
  std::filesystem::remove_all(dir);
  const std::string path = dir + "/steps.csv";
  CsvWriter csv({"step", "time"});
  csv.addRow(0, 0.0);
  csv.write(path);
  csv.addRow(1, 0.25);
  csv.write(path);
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_EQ(s.str(), "step,time\n0,0\n1,0.25\n");
  EXPECT_EQ(test::listDirectory(dir), std::vector<std::string>{"steps.csv"});
}

}  // namespace
}  // namespace contactlab
