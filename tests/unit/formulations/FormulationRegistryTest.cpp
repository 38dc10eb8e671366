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

}  // namespace
}  // namespace contactlab
