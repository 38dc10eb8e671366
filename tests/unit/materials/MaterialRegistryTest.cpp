// The material registry: the laws' entries with documented parameters, and parameter
// validation that names the refused key.
#include "core/materials/J2SmallStrain.hpp"
#include "core/materials/MaterialRegistry.hpp"
#include "core/materials/NeoHookean.hpp"

#include <Teuchos_ParameterList.hpp>

#include <gtest/gtest.h>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace contactlab {
namespace {

std::unique_ptr<Material> build(const std::string& name,
                                const std::vector<std::pair<std::string, double>>& values) {
  registerMaterials();
  const auto& entry = materialRegistry().get(name);
  Teuchos::ParameterList p(*entry.validParameters());  // defaults, as the scene reader fills in
  for (const auto& [key, value] : values)
    p.set(key, value);
  return entry.build(p);
}

// The message of the std::invalid_argument thrown by build(), or "" when none is.
std::string buildError(const std::string& name,
                       const std::vector<std::pair<std::string, double>>& values) {
  try {
    build(name, values);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(MaterialRegistry, NewLawsAreRegisteredWithDocumentedParameters) {
  registerMaterials();
  for (const std::string name : {"saint-venant-kirchhoff", "neo-hookean", "j2-small-strain"}) {
    ASSERT_TRUE(materialRegistry().has(name)) << name;
    const auto& entry = materialRegistry().get(name);
    EXPECT_FALSE(entry.doc.empty()) << name;
    const auto valid = entry.validParameters();
    for (auto it = valid->begin(); it != valid->end(); ++it)
      EXPECT_FALSE(valid->entry(it).docString().empty()) << name << ": " << valid->name(it);
  }
  const auto svk = build("saint-venant-kirchhoff", {{"E", 3.0}, {"density", 2.0}});
  EXPECT_EQ(svk->name(), "saint-venant-kirchhoff");
  EXPECT_EQ(svk->kinematics(), Kinematics::FiniteStrain);
  EXPECT_EQ(svk->density(), 2.0);
  const auto nh = build("neo-hookean", {{"C10", 1.0}, {"D1", 0.5}});
  EXPECT_EQ(nh->kinematics(), Kinematics::FiniteStrain);
  EXPECT_EQ(dynamic_cast<const NeoHookean&>(*nh).shearModulus(), 2.0);
  EXPECT_EQ(dynamic_cast<const NeoHookean&>(*nh).bulkModulus(), 4.0);
  const auto nhE = build("neo-hookean", {{"E", 2.6}, {"nu", 0.3}});
  EXPECT_NEAR(dynamic_cast<const NeoHookean&>(*nhE).shearModulus(), 1.0, 1e-14);
  const auto j2 = build("j2-small-strain", {{"Yield Stress", 0.01},
                                            {"Isotropic Hardening Modulus", 0.1},
                                            {"Kinematic Hardening Modulus", 0.2}});
  EXPECT_EQ(j2->kinematics(), Kinematics::SmallStrain);
  EXPECT_EQ(j2->stateSize(), 13);
  const auto& params = dynamic_cast<const J2SmallStrain&>(*j2).parameters();
  EXPECT_EQ(params.yieldStress.at(20.0), 0.01);
  EXPECT_EQ(params.isotropicHardening.at(20.0), 0.1);
  EXPECT_EQ(params.kinematicHardening.at(20.0), 0.2);
}

struct Refusal {
  std::string law;
  std::vector<std::pair<std::string, double>> values;
  std::vector<std::string> expected;  // substrings of the message
};

TEST(MaterialRegistry, InvalidParametersAreRefusedNamingTheKey) {
  const std::vector<Refusal> refusals = {
      {"saint-venant-kirchhoff", {{"E", 0.0}}, {"E must be > 0", "(got 0)"}},
      {"saint-venant-kirchhoff", {{"E", -2.0}}, {"E must be > 0", "(got -2)"}},
      {"saint-venant-kirchhoff", {{"nu", 0.5}}, {"nu must lie in (-1, 0.5)", "(got 0.5)"}},
      {"saint-venant-kirchhoff", {{"nu", -1.0}}, {"nu must lie in (-1, 0.5)", "(got -1)"}},
      {"saint-venant-kirchhoff", {{"density", -1.0}}, {"density must be >= 0", "(got -1)"}},
      {"neo-hookean", {{"E", -1.0}}, {"E must be > 0", "(got -1)"}},
      {"neo-hookean", {{"E", 1.0}, {"nu", 0.5}}, {"nu must lie in (-1, 0.5)", "(got 0.5)"}},
      {"neo-hookean", {{"E", 1.0}, {"nu", 0.7}}, {"nu must lie in (-1, 0.5)", "(got 0.7)"}},
      {"neo-hookean", {{"E", 1.0}, {"nu", -1.0}}, {"nu must lie in (-1, 0.5)", "(got -1)"}},
      {"neo-hookean", {{"C10", -1.0}, {"D1", 0.1}}, {"C10 must be > 0", "(got -1)"}},
      {"neo-hookean", {{"D1", 0.1}}, {"C10 must be > 0", "(got 0)"}},
      {"neo-hookean", {{"C10", 1.0}, {"D1", -0.1}}, {"D1 must be > 0", "(got -0.1)"}},
      {"neo-hookean", {{"C10", 1.0}}, {"D1 must be > 0", "(got 0)"}},
      {"neo-hookean", {{"E", 1.0}, {"C10", 1.0}, {"D1", 0.1}}, {"not both", "E = 1", "C10 = 1"}},
      {"neo-hookean", {{"E", 2.0}, {"D1", 0.1}}, {"not both", "E = 2", "D1 = 0.1"}},
      {"neo-hookean", {}, {"give either E and nu or C10 and D1"}},
      {"neo-hookean", {{"C10", 1.0}, {"D1", 0.1}, {"nu", 0.25}}, {"nu is used only with E"}},
      {"neo-hookean", {{"E", 1.0}, {"density", -1.0}}, {"density must be >= 0", "(got -1)"}},
      {"j2-small-strain", {}, {"Yield Stress must be > 0", "(got 0)"}},
      {"j2-small-strain", {{"Yield Stress", -1.0}}, {"Yield Stress must be > 0", "(got -1)"}},
      {"j2-small-strain", {{"Yield Stress", 1.0}, {"E", 0.0}}, {"E must be > 0", "(got 0)"}},
      {"j2-small-strain", {{"Yield Stress", 1.0}, {"nu", 0.5}}, {"nu must lie in", "(got 0.5)"}},
      {"j2-small-strain",
       {{"Yield Stress", 1.0}, {"Isotropic Hardening Modulus", -1.0}},
       {"Isotropic Hardening Modulus must be >= 0", "(got -1)"}},
      {"j2-small-strain",
       {{"Yield Stress", 1.0}, {"Kinematic Hardening Modulus", -1.0}},
       {"Kinematic Hardening Modulus must be >= 0", "(got -1)"}},
      {"j2-small-strain",
       {{"Yield Stress", 1.0}, {"density", -1.0}},
       {"density must be >= 0", "(got -1)"}},
  };
  for (const auto& r : refusals) {
    const std::string what = buildError(r.law, r.values);
    ASSERT_FALSE(what.empty()) << r.law << ": no error for " << r.expected.front();
    EXPECT_EQ(what.rfind(r.law + ": ", 0), 0u) << what;
    for (const auto& s : r.expected)
      EXPECT_NE(what.find(s), std::string::npos) << "'" << s << "' not in: " << what;
  }
  // The boundaries that are valid.
  EXPECT_EQ(buildError("j2-small-strain", {{"Yield Stress", 1.0}}), "");
  EXPECT_EQ(buildError("neo-hookean", {{"E", 1.0}, {"nu", -0.99}}), "");
  EXPECT_EQ(buildError("neo-hookean", {{"C10", 1.0}, {"D1", 0.1}}), "");
  EXPECT_EQ(buildError("saint-venant-kirchhoff", {}), "");
}

}  // namespace
}  // namespace contactlab
