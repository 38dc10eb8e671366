#include "MpiTestUtils.hpp"
#include "TestMeshes.hpp"

#include "base/InputError.hpp"
#include "core/io/OutputFolder.hpp"
#include "core/io/OutputManifest.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

namespace fs = std::filesystem;

// Each rank works in its own folder: the test runs on 1 and 2 ranks at once.
std::string freshDir(const std::string& name) {
  const std::string dir = test::testOutputDir("manifest", test::commSize()) + "/rank" +
                          std::to_string(test::commRank()) + "/" + name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void touch(const std::string& path) {
  std::ofstream(path) << "x\n";
}

TEST(OutputManifest, ListsEachNameOnceBeforeItsFile) {
  const std::string dir = freshDir("list");
  OutputManifest manifest(dir, true);
  EXPECT_EQ(manifest.path("steps.csv"), dir + "/steps.csv");
  manifest.add({"steps.csv", "result.pvd"});
  EXPECT_FALSE(fs::exists(dir + "/steps.csv"));  // listed, not written
  EXPECT_EQ(*OutputManifest::read(dir), (std::vector<std::string>{"steps.csv", "result.pvd"}));
  // A continued run goes on with the list.
  OutputManifest again(dir, true);
  again.add({"result.pvd", "summary.json"});
  EXPECT_EQ(OutputManifest::read(dir)->size(), 3u);
  // Other ranks list nothing.
  OutputManifest silent(freshDir("silent"), false);
  silent.add({"steps.csv"});
  EXPECT_FALSE(OutputManifest::read(silent.folder()).has_value());
  EXPECT_THROW(manifest.add({"../up.csv"}), std::logic_error);
}

TEST(OutputManifest, ReadsPlainNamesOfFinishedLinesOnly) {
  const std::string dir = freshDir("read");
  EXPECT_FALSE(OutputManifest::read(dir).has_value());
  std::ofstream(dir + "/" + OutputManifest::kFileName)
      << "steps.csv\n../victim.txt\n/etc/hostname\n..\n.\n\nsummary.json\nresult_0000";
  EXPECT_EQ(*OutputManifest::read(dir), (std::vector<std::string>{"steps.csv", "summary.json"}));
}

TEST(OutputFolder, RemovesWhatTheEarlierRunListedAndNothingElse) {
  const std::string dir = freshDir("clean");
  for (const char* f : {"steps.csv", "result_000003.vtu", ".steps.csv.tmp.42", "contact_t5.csv",
                        "notes.txt", ".summary.json.tmp.7"})
    touch(dir + "/" + f);
  OutputManifest::write(dir, {"steps.csv", "result_000003.vtu", "summary.json"});
  const std::vector<std::string> removed = prepareOutputFolder(dir);
  EXPECT_EQ(removed.size(), 4u);  // steps.csv, result_000003.vtu and two temporaries
  EXPECT_EQ(test::listDirectory(dir),
            (std::vector<std::string>{".contactlab-outputs", "contact_t5.csv", "notes.txt"}));
  EXPECT_TRUE(OutputManifest::read(dir)->empty());  // this run's list, started
}

TEST(OutputFolder, WithoutAManifestRemovesTheRunsOutputNamesOnly) {
  const std::string dir = freshDir("older");
  for (const char* f : {"steps.csv", "result_000003.vtu", ".steps.csv.tmp.42", "profile_a.csv",
                        "notes.txt", "plot.png"})
    touch(dir + "/" + f);
  EXPECT_EQ(prepareOutputFolder(dir).size(), 4u);
  EXPECT_EQ(test::listDirectory(dir),
            (std::vector<std::string>{".contactlab-outputs", "notes.txt", "plot.png"}));
}

TEST(OutputFolder, PlainNamesOnly) {
  for (const char* bad : {"", "  ", ".", "..", "a/b", "../x", "x..y", "tab\there"})
    EXPECT_THROW(requirePlainName(bad, "Name", "results/<Name>"), InputError) << bad;
  EXPECT_NO_THROW(requirePlainName("hertz-2d v2.1", "Name", "results/<Name>"));
}

}  // namespace
}  // namespace contactlab
