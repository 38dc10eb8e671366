// The element-count estimate that guards the generators against requests that would exhaust
// memory: exact for the structured ones, an order of magnitude for the graded ones (checked
// against what gmsh makes), and a refusal in a sentence before meshing.
#include "core/mesh/ElementEstimate.hpp"

#include <chrono>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

TEST(ElementEstimate, StructuredCountsAreExact) {
  RectangleParams r;
  r.divisions = {7, 3};
  r.elementType = "tri6";
  EXPECT_EQ(estimateElements(r), double(generateRectangle(r).numElements()));
  BoxParams b;
  b.divisions = {2, 3, 2};
  b.elementType = "tet4";
  EXPECT_EQ(estimateElements(b), double(generateBox(b).numElements()));
}

void expectOrderOfMagnitude(double estimate, std::size_t actual, const char* what) {
  EXPECT_GT(estimate, actual / 3.0) << what << ": estimate " << estimate << ", gmsh " << actual;
  EXPECT_LT(estimate, actual * 3.0) << what << ": estimate " << estimate << ", gmsh " << actual;
}

TEST(ElementEstimate, GradedCountsAreTheRightOrderOfMagnitude) {
  HalfDiscParams d;
  d.grading = {0.01, 0.2, 0.05, 0.5};
  expectOrderOfMagnitude(estimateElements(d), generateHalfDisc(d).numElements(), "half-disc tri3");
  d.elementType = "quad4";
  expectOrderOfMagnitude(estimateElements(d), generateHalfDisc(d).numElements(), "half-disc quad4");
  RollerOnBaseParams rb;
  expectOrderOfMagnitude(estimateElements(rb), generateRollerOnBase(rb).numElements(),
                         "roller-on-base");
  BladeRootParams blade;
  expectOrderOfMagnitude(estimateElements(blade), generateBladeRoot(blade).numElements(),
                         "blade-root quad4");
  blade.elementType = "tri3";
  blade.lobes = 3;
  blade.sizeFlank = 0.2;
  expectOrderOfMagnitude(estimateElements(blade), generateBladeRoot(blade).numElements(),
                         "blade-root tri3, 3 lobes");
  blade.elementType = "hex8";
  blade.sizeFlank = 0.5;
  expectOrderOfMagnitude(estimateElements(blade), generateBladeRoot(blade).numElements(),
                         "blade-root hex8, swept");
  HalfSphereParams s;
  expectOrderOfMagnitude(estimateElements(s), generateHalfSphere(s).numElements(), "half-sphere");
  s.base = "block";
  expectOrderOfMagnitude(estimateElements(s), generateHalfSphere(s).numElements(),
                         "half-sphere on a block");
}

TEST(ElementEstimate, HugeRequestsAreRefusedBeforeMeshing) {
  const auto start = std::chrono::steady_clock::now();
  RectangleParams r;
  r.divisions = {100000, 100000};
  EXPECT_THROW(requireElementLimit("rectangle", estimateElements(r), kDefaultMaxElements),
               std::invalid_argument);
  HalfSphereParams s;
  s.grading.sizeContact = 1e-5;
  try {
    requireElementLimit("half-sphere", estimateElements(s), kDefaultMaxElements);
    ADD_FAILURE() << "a 3D Size Contact of 1e-5 was not refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("Max Elements"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
}

}  // namespace
}  // namespace contactlab
