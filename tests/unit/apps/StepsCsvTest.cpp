// StepsCsv: the columns of steps.csv, each step's share of the cumulated contact timers, and
// the largest condition estimate for the summary.
#include "apps/output/StepsCsv.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace contactlab {
namespace {

std::vector<std::vector<std::string>> readCsv(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');)
      cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    rows.push_back(cells);
  }
  return rows;
}

std::string column(const std::vector<std::vector<std::string>>& rows, int row,
                   const std::string& name) {
  for (std::size_t c = 0; c < rows[0].size(); ++c)
    if (rows[0][c] == name) return rows[row][c];
  ADD_FAILURE() << "no column " << name;
  return {};
}

// A folder of this process's own.
std::string scratch(const std::string& name) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                       ("contactlab-" + std::to_string(::getpid()) + "-" + name);
  std::filesystem::create_directories(folder);
  return folder.string();
}

TEST(StepsCsv, CriticalMuColumnOnlyWhenTheCheckRuns) {
  const std::string with = scratch("with"), without = scratch("without");
  OutputManifest withFolder(with, true), withoutFolder(without, true);
  StepsCsv a(withFolder, true), b(withoutFolder, false);
  StepReport s;
  s.step = 1;
  a.addStep(s, {}, std::nullopt, std::nullopt, std::string("inf"));
  b.addStep(s, {}, std::nullopt, std::nullopt, std::nullopt);
  a.write();
  b.write();
  const auto ra = readCsv(with + "/steps.csv"), rb = readCsv(without + "/steps.csv");
  EXPECT_EQ(ra[0].back(), "critical_mu");
  EXPECT_EQ(column(ra, 1, "critical_mu"), "inf");
  EXPECT_EQ(ra[0].size(), rb[0].size() + 1);
  EXPECT_EQ(rb[0].back(), "linear_solve_s");
  EXPECT_EQ(*OutputManifest::read(with), std::vector<std::string>{"steps.csv"});
  std::filesystem::remove_all(with);
  std::filesystem::remove_all(without);
}

// The force history: sum w p and the vector sum of the normal and tangential forces.
TEST(StepsCsv, ContactForceColumns) {
  const std::string folder = scratch("force");
  OutputManifest manifest(folder, true);
  StepsCsv csv(manifest, false);
  StepReport s;
  s.step = 1;
  ContactResultants r;
  r.normalForceMagnitude = 5.0;
  r.normalForce = {0.5, 0.0, -4.0};
  r.tangentialForce = {1.5, 0.25, 0.125};
  csv.addStep(s, r, std::nullopt, std::nullopt, std::nullopt);
  csv.write();
  const auto rows = readCsv(folder + "/steps.csv");
  EXPECT_DOUBLE_EQ(std::stod(column(rows, 1, "normal_force")), 5.0);
  EXPECT_DOUBLE_EQ(std::stod(column(rows, 1, "contact_force_x")), 2.0);
  EXPECT_DOUBLE_EQ(std::stod(column(rows, 1, "contact_force_y")), 0.25);
  EXPECT_DOUBLE_EQ(std::stod(column(rows, 1, "contact_force_z")), -3.875);
  std::filesystem::remove_all(folder);
}

// The contact problem's timers are cumulated over the run: each row gets its step's share of
// each (the solid's assembly, pairing, contact terms), never a difference of two timers (the
// contact terms taken out of the Newton solves' assembly seconds came out negative where contact
// was evaluated outside them). Without contact, assembly_s is the step's assembly seconds.
TEST(StepsCsv, PhaseSecondsAreEachStepsShare) {
  const std::string folder = scratch("phases");
  OutputManifest manifest(folder, true);
  StepsCsv csv(manifest, false);
  StepReport s;
  s.step = 1;
  s.seconds.assembly = 0.001;  // a step's Newton assemblies: not what the contact rows print
  csv.addStep(s, {}, 10.0, ContactPhaseSeconds{1.0, 3.0, 2.0}, std::nullopt);
  s.step = 2;
  csv.addStep(s, {}, 30.0, ContactPhaseSeconds{1.5, 7.5, 2.5}, std::nullopt);
  s.seconds.assembly = 5.0;
  csv.addStep(s, {}, std::nullopt, std::nullopt, std::nullopt);
  csv.write();
  const auto rows = readCsv(folder + "/steps.csv");
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_DOUBLE_EQ(std::stod(column(rows, 1, "pairing_s")), 1.0);
  EXPECT_DOUBLE_EQ(std::stod(column(rows, 1, "assembly_s")), 3.0);
  EXPECT_DOUBLE_EQ(std::stod(column(rows, 1, "contact_s")), 2.0);
  EXPECT_DOUBLE_EQ(std::stod(column(rows, 2, "pairing_s")), 0.5);
  EXPECT_DOUBLE_EQ(std::stod(column(rows, 2, "contact_s")), 0.5);
  EXPECT_DOUBLE_EQ(std::stod(column(rows, 2, "assembly_s")), 4.5);
  EXPECT_DOUBLE_EQ(std::stod(column(rows, 3, "assembly_s")), 5.0);
  EXPECT_DOUBLE_EQ(std::stod(column(rows, 3, "pairing_s")), 0.0);
  EXPECT_EQ(column(rows, 3, "condition_estimate"), "");
  EXPECT_DOUBLE_EQ(csv.maxConditionEstimate(), 30.0);
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace contactlab
