// The linear solver registry: names, documented parameters, builders, validation errors.
#include "linear/LinearSolverRegistry.hpp"

#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>

namespace contactlab {
namespace {

Teuchos::RCP<const Comm> world() {
  return Tpetra::getDefaultComm();
}

TEST(LinearSolverRegistry, HasMumpsKlu2AndBelosInThatOrder) {
  registerLinearSolvers();
  registerLinearSolvers();  // idempotent
  EXPECT_EQ(linearSolverRegistry().names(), (std::vector<std::string>{"mumps", "klu2", "belos"}));
}

// The uniqueness checks ask the registry, not a list of names, which solver has determinants.
TEST(LinearSolverRegistry, OnlyMumpsComputesDeterminants) {
  registerLinearSolvers();
  EXPECT_TRUE(computesDeterminant("mumps"));
  EXPECT_FALSE(computesDeterminant("klu2"));
  EXPECT_FALSE(computesDeterminant("belos"));
  EXPECT_EQ(solversComputingDeterminant(), "mumps");
  Teuchos::ParameterList belos;
  EXPECT_THROW(buildDeterminantSolver("belos", belos, world()), LinearSolverError);
}

TEST(LinearSolverRegistry, UnknownNameErrorListsTheValidNames) {
  registerLinearSolvers();
  try {
    linearSolverRegistry().get("superlu");
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'superlu'"), std::string::npos) << what;
    EXPECT_NE(what.find("mumps, klu2, belos"), std::string::npos) << what;
  }
}

TEST(LinearSolverRegistry, EveryParameterHasADefaultAndADocString) {
  registerLinearSolvers();
  for (const auto& name : linearSolverRegistry().names()) {
    const auto& entry = linearSolverRegistry().get(name);
    EXPECT_FALSE(entry.doc.empty()) << name;
    const auto valid = entry.validParameters();
    EXPECT_GT(valid->numParams(), 0) << name;
    for (auto it = valid->begin(); it != valid->end(); ++it) {
      const auto& e = valid->entry(it);
      EXPECT_FALSE(e.isList()) << name << ": " << valid->name(it);
      EXPECT_FALSE(e.docString().empty()) << name << ": " << valid->name(it);
      EXPECT_FALSE(e.getAny(false).empty()) << name << ": " << valid->name(it);
    }
  }
}

TEST(LinearSolverRegistry, BuildsEachSolverFromDefaults) {
  registerLinearSolvers();
  for (const auto& name : linearSolverRegistry().names()) {
    const auto& entry = linearSolverRegistry().get(name);
    Teuchos::ParameterList params(*entry.validParameters());
    auto solver = entry.build(params, world());
    ASSERT_TRUE(solver) << name;
    EXPECT_EQ(solver->name(), name);
    auto fromEmpty = entry.build(Teuchos::ParameterList(), world());  // defaults filled in
    EXPECT_EQ(fromEmpty->stats().solves, 0);
  }
}

TEST(LinearSolverRegistry, InvalidParametersAreLinearSolverErrors) {
  registerLinearSolvers();
  const auto& mumps = linearSolverRegistry().get("mumps");
  Teuchos::ParameterList badChoice;
  badChoice.set("Ordering", "metis");  // not built into Debian's MUMPS
  EXPECT_THROW(mumps.build(badChoice, world()), LinearSolverError);
  Teuchos::ParameterList misspelt;
  misspelt.set("Ordring", "amd");
  EXPECT_THROW(mumps.build(misspelt, world()), LinearSolverError);
  Teuchos::ParameterList badValue;
  badValue.set("Tolerance", -1.0);
  EXPECT_THROW(linearSolverRegistry().get("belos").build(badValue, world()), LinearSolverError);
}

// Mode 'automatic' is resolved by the registry's convention (a string parameter Mode), not by
// the type's name: MUMPS takes the tangent's symmetry, a given Mode stays, klu2 has none.
TEST(LinearSolverRegistry, AutomaticModeFollowsTheTangentWhereTheTypeHasAMode) {
  registerLinearSolvers();
  auto section = [](const std::string& type, const std::string& mode) {
    Teuchos::ParameterList p;
    p.set("Type", type);
    if (!mode.empty()) p.sublist(type).set("Mode", mode);
    return p;
  };
  Teuchos::ParameterList mumps = section("mumps", "automatic");
  resolveAutomaticMode(mumps, true);
  EXPECT_EQ(mumps.sublist("mumps").get<std::string>("Mode"), "symmetric-indefinite");
  Teuchos::ParameterList unsymmetric = section("mumps", "");
  resolveAutomaticMode(unsymmetric, false);
  EXPECT_EQ(unsymmetric.sublist("mumps").get<std::string>("Mode"), "general");
  Teuchos::ParameterList given = section("mumps", "symmetric");
  resolveAutomaticMode(given, false);
  EXPECT_EQ(given.sublist("mumps").get<std::string>("Mode"), "symmetric");
  recordGeneralMode(given);
  EXPECT_EQ(given.sublist("mumps").get<std::string>("Mode"), "general");
  Teuchos::ParameterList klu2 = section("klu2", "");
  resolveAutomaticMode(klu2, true);
  recordGeneralMode(klu2);
  EXPECT_FALSE(klu2.sublist("klu2").isParameter("Mode"));
}

}  // namespace
}  // namespace contactlab
