// referenceYoungModulus reads E back from each registered law's tangent at rest, elastic or
// plastic, small or finite strain (the scale of the automatic contact coefficients).
#include "core/materials/MaterialRegistry.hpp"
#include "core/materials/ReferenceStiffness.hpp"

#include <Teuchos_ParameterList.hpp>

#include <gtest/gtest.h>
#include <string>

namespace contactlab {
namespace {

TEST(ReferenceStiffness, EveryRegisteredLawGivesBackItsE) {
  registerMaterials();
  for (const std::string& name : materialRegistry().names()) {
    const auto& entry = materialRegistry().get(name);
    Teuchos::ParameterList p(*entry.validParameters());
    p.set("E", 210.0);
    p.set("nu", 0.3);
    if (p.isParameter("Yield Stress")) p.set("Yield Stress", 1.0);  // plastic at once if strained
    const auto material = entry.build(p);
    EXPECT_NEAR(referenceYoungModulus(*material), 210.0, 210.0 * 1e-12) << name;
  }
}

TEST(ReferenceStiffness, NearlyIncompressibleIsThreeTimesTheShearModulus) {
  registerMaterials();
  const auto& entry = materialRegistry().get("neo-hookean");
  Teuchos::ParameterList p(*entry.validParameters());
  p.set("C10", 0.5);  // mu = 1
  p.set("D1", 1e-9);  // K = 2e9
  EXPECT_NEAR(referenceYoungModulus(*entry.build(p)), 3.0, 1e-8);
}

}  // namespace
}  // namespace contactlab
