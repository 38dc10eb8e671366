#include "MpiTestUtils.hpp"
#include "TestMeshes.hpp"

#include "core/io/AtomicFile.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <stdexcept>

namespace contactlab {
namespace {

std::string readAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Each rank works in its own folder: the test runs on 1 and 2 ranks at once.
std::string rankDir(const std::string& name) {
  return test::testOutputDir("atomic", test::commSize()) + "/rank" +
         std::to_string(test::commRank()) + "/" + name;
}

void freshRankDir(const std::string& dir) {
  std::filesystem::remove_all(dir);
}

TEST(AtomicFile, WritesAndCreatesParentDirectories) {
  const std::string dir = rankDir("create");
  freshRankDir(dir);
  const std::string path = dir + "/a/b/file.txt";
  writeFileAtomically(path, [](std::ostream& out) { out << "hello\n"; });
  EXPECT_EQ(readAll(path), "hello\n");
  EXPECT_EQ(test::listDirectory(dir + "/a/b"), std::vector<std::string>{"file.txt"});
}

TEST(AtomicFile, ThrowingWriterLeavesNeitherTemporaryNorPartialFile) {
  const std::string dir = rankDir("throw");
  freshRankDir(dir);
  const std::string path = dir + "/result.csv";
  EXPECT_THROW(writeFileAtomically(path,
                                   [](std::ostream& out) {
                                     out << "half a line";
                                     out.flush();
                                     throw std::runtime_error("simulated crash");
                                   }),
               std::runtime_error);
  EXPECT_TRUE(test::listDirectory(dir).empty());
}

TEST(AtomicFile, ThrowingWriterKeepsPreviousVersion) {
  const std::string dir = rankDir("keep");
  freshRankDir(dir);
  const std::string path = dir + "/steps.csv";
  writeFileAtomically(path, [](std::ostream& out) { out << "complete\n"; });
  EXPECT_THROW(writeFileAtomically(path,
                                   [](std::ostream& out) {
                                     out << "partial";
                                     throw std::logic_error("bug");
                                   }),
               std::logic_error);
  EXPECT_EQ(readAll(path), "complete\n");
  EXPECT_EQ(test::listDirectory(dir), std::vector<std::string>{"steps.csv"});
}

TEST(AtomicFile, ErrorNamesTheFile) {
  const std::string dir = rankDir("error");
  freshRankDir(dir);
  // A regular file where a directory is needed fails even for root (unlike permissions).
  writeFileAtomically(dir + "/blocker", [](std::ostream& out) { out << "x"; });
  const std::string path = dir + "/blocker/sub/result.pvd";
  try {
    writeFileAtomically(path, [](std::ostream& out) { out << "x"; });
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write results to '" + path + "'"),
              std::string::npos)
        << e.what();
  }
}

TEST(AtomicFile, TemporaryIsHiddenNextToTargetUntilCommitted) {
  const std::string dir = rankDir("commit");
  freshRankDir(dir);
  const std::string path = dir + "/piece.vtu";
  const std::string temporary = temporaryPathFor(path);
  EXPECT_EQ(std::filesystem::path(temporary).parent_path(), std::filesystem::path(dir));
  EXPECT_EQ(std::filesystem::path(temporary).filename().string().rfind(".piece.vtu.tmp.", 0), 0u);
  { std::ofstream(temporary) << "data"; }
  EXPECT_FALSE(std::filesystem::exists(path));
  commitFile(temporary, path);
  EXPECT_EQ(readAll(path), "data");
  EXPECT_EQ(test::listDirectory(dir), std::vector<std::string>{"piece.vtu"});

  const std::string orphan = temporaryPathFor(path);
  { std::ofstream(orphan) << "more"; }
  discardFile(orphan);
  EXPECT_EQ(test::listDirectory(dir), std::vector<std::string>{"piece.vtu"});
}

TEST(AtomicFile, FailedCommitRemovesTemporary) {
  const std::string dir = rankDir("failedcommit");
  freshRankDir(dir);
  std::filesystem::create_directories(dir + "/target_is_a_dir/child");
  const std::string temporary = temporaryPathFor(dir + "/target_is_a_dir");
  { std::ofstream(temporary) << "data"; }
  EXPECT_THROW(commitFile(temporary, dir + "/target_is_a_dir"), std::runtime_error);
  EXPECT_EQ(test::listDirectory(dir), std::vector<std::string>{"target_is_a_dir"});
}

}  // namespace
}  // namespace contactlab
