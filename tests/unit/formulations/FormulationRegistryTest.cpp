// The formulation registry: required coefficients left at their defaults are refused by name.
#include "tests/unit/formulations/ContactLawTestSupport.hpp"

#include "formulations/FormulationRegistry.hpp"

#include <gtest/gtest.h>
#include <stdexcept>
#include <string>

namespace contactlab {
namespace {

using namespace test;

TEST(FormulationRegistry, DefaultsOfRequiredCoefficientsAreRejectedByName) {
  registerFormulations();
  registerFormulations();  // idempotent
  auto& registry = formulationRegistry();
  EXPECT_EQ(registry.names().size(), 4u);
  for (const char* name : kLawNames)
    ASSERT_TRUE(registry.has(name)) << name;

  const std::pair<const char*, const char*> required[] = {
      {"penalty", "Normal Penalty"},
      {"lagrange", "Normal Complementarity Constant"},
      {"augmented-lagrangian", "Normal Augmentation"},
      {"normal-field-augmented-lagrangian", "Normal Augmentation"}};
  for (const auto& [name, key] : required) {
    const auto& entry = registry.get(name);
    const auto defaults = entry.validParameters();
    try {
      entry.build(*defaults);
      ADD_FAILURE() << name << " built with its default (zero) coefficients";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }

  // With the required coefficient given, the unused tangential one may stay at its default.
  for (const auto& [name, key] : required) {
    const auto& entry = registry.get(name);
    Teuchos::ParameterList params(*entry.validParameters());
    params.set(key, 10.0);
    std::unique_ptr<ContactLaw> built;
    ASSERT_NO_THROW(built = entry.build(params)) << name;
    EXPECT_EQ(built->name(), name);
  }
  EXPECT_THROW(registry.get("no-such-law"), std::invalid_argument);
}

// Each automatic coefficient is a parameter of its formulation whose default is 0 (automatic),
// with its rule on the scale: c_n and r_n = E / h, r_t = 1 / (0.01 mu h); the penalty has none
// (its coefficients are the model's: they set the penetration).
TEST(FormulationRegistry, AutomaticCoefficientsAreZeroDefaultsWithTheirRule) {
  registerFormulations();
  const ContactScale scale{200.0, 0.05};  // E / h = 4000
  EXPECT_TRUE(automaticCoefficients("penalty").empty());
  EXPECT_TRUE(automaticCoefficients("no-such-formulation").empty());
  const auto& lagrange = automaticCoefficients("lagrange");
  ASSERT_EQ(lagrange.size(), 1u);
  EXPECT_EQ(lagrange[0].key, "Normal Complementarity Constant");
  EXPECT_DOUBLE_EQ(lagrange[0].value(scale, 0.3), 4000.0);
  for (const char* name : {"augmented-lagrangian", "normal-field-augmented-lagrangian"}) {
    const auto& list = automaticCoefficients(name);
    ASSERT_EQ(list.size(), 2u) << name;
    EXPECT_EQ(list[0].key, "Normal Augmentation");
    EXPECT_FALSE(list[0].needsFriction);
    EXPECT_DOUBLE_EQ(list[0].value(scale, 0.5), 4000.0);
    EXPECT_EQ(list[1].key, "Tangential Augmentation");
    EXPECT_TRUE(list[1].needsFriction);
    EXPECT_DOUBLE_EQ(list[1].value(scale, 0.5), 1.0 / (0.01 * 0.5 * 0.05));
    EXPECT_NE(list[1].note(scale, 0.5, 4e4).find("r_t = 1 / (0.01 mu h) = 40000"),
              std::string::npos)
        << list[1].note(scale, 0.5, 4e4);
  }
  for (const std::string& name : formulationRegistry().names()) {
    const auto params = formulationRegistry().get(name).validParameters();
    for (const AutomaticCoefficient& c : automaticCoefficients(name)) {
      ASSERT_TRUE(params->isParameter(c.key)) << name << ": " << c.key;
      EXPECT_EQ(params->get<double>(c.key), 0.0) << name << ": " << c.key;
    }
  }
}

}  // namespace
}  // namespace contactlab
