// Which overlapping masters a slave facet integrates against (MortarMasterSelection.hpp): the
// surface nearest to it, facing it, within the search distance. Each case would fail with every
// overlapping master counted (the 3D blade root's defect: a second surface behind the one
// touched doubled D and averaged the gaps of both).
#include "tests/unit/contact/MortarTestSupport.hpp"

#include "core/contact/MortarIntegration.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace contactlab {
namespace {

using namespace test;

void expectSame(const MortarIntegrals& a, const MortarIntegrals& b) {
  EXPECT_NEAR(a.coveredArea, b.coveredArea, 1e-14);
  ASSERT_EQ(a.D.size(), b.D.size());
  for (std::size_t k = 0; k < a.D.size(); ++k)
    EXPECT_NEAR(a.D[k], b.D[k], 1e-14);
  ASSERT_EQ(a.masters.size(), b.masters.size());
  for (std::size_t m = 0; m < a.masters.size(); ++m) {
    EXPECT_EQ(a.masters[m].facet, b.masters[m].facet);
    for (std::size_t k = 0; k < a.masters[m].M.size(); ++k)
      EXPECT_NEAR(a.masters[m].M[k], b.masters[m].M[k], 1e-14);
  }
}

// The patch cases' slaves face +z in 3D (before `place`) and -y in 2D: "behind" is the other way.
double behind(const PatchCase& c, double distance) {
  return isLine(c.slave) ? distance : -distance;
}

TEST(MortarMasterSelection, ASurfaceBehindTheNearestIsIgnored) {
  for (const PatchCase& c : kPatchCases)
    for (MultiplierBasis basis : kBases) {
      SCOPED_TRACE(std::string(info(c.slave).name) + " on " + info(c.master).name);
      const Facet slave = makeFacet(c.slave, unitSlave(c.slave));
      const std::vector<Facet> near = patchMasters(c);
      std::vector<Facet> both = near;
      for (Facet f : patchMasters(c, behind(c, 3.0))) {  // 3 unit facets behind, facing it too
        f.tag += 1000;
        both.push_back(f);
      }
      const auto normals = nodeNormals(slave);
      const MortarIntegrals alone = integrateMortar(slave, normals, pointers(near), basis);
      const MortarIntegrals selected = integrateMortar(slave, normals, pointers(both), basis);
      ASSERT_GT(alone.coveredArea, 0.0);
      expectSame(selected, alone);
    }
}

TEST(MortarMasterSelection, MastersFacingAwayAreIgnored) {
  for (ElementType t : {ElementType::Line2, ElementType::Tri3, ElementType::Quad9}) {
    SCOPED_TRACE(info(t).name);
    const Facet slave = makeFacet(t, unitSlave(t));
    const Facet facing = makeMaster(t, unitSlave(t)), away = makeFacet(t, unitSlave(t));
    const auto normals = nodeNormals(slave);
    EXPECT_NEAR(integrateMortar(slave, normals, {&facing}, MultiplierBasis::Dual).coveredArea,
                integrateMortar(slave, normals, {&facing}, MultiplierBasis::Dual).area, 1e-14);
    const MortarIntegrals r = integrateMortar(slave, normals, {&away}, MultiplierBasis::Dual);
    EXPECT_EQ(r.coveredArea, 0.0);
    EXPECT_TRUE(r.masters.empty());
  }
}

// "Master points farther than this from a slave point are ignored" (Search Distance).
TEST(MortarMasterSelection, TheSearchDistanceBoundsTheGap) {
  for (const PatchCase& c : {kPatchCases[0], kPatchCases[4], kPatchCases[8]}) {
    SCOPED_TRACE(std::string(info(c.slave).name) + " on " + info(c.master).name);
    const Facet slave = makeFacet(c.slave, unitSlave(c.slave));
    const std::vector<Facet> masters = patchMasters(c, -behind(c, 0.37));  // open, 0.37 off
    const auto normals = nodeNormals(slave);
    const auto integrate = [&](double searchDistance) {
      return integrateMortar(slave, normals, pointers(masters), MultiplierBasis::Dual, {},
                             searchDistance);
    };
    EXPECT_EQ(integrate(0.3).coveredArea, 0.0);
    EXPECT_TRUE(integrate(0.3).masters.empty());
    expectSame(integrate(0.5), integrate(HUGE_VAL));
    EXPECT_GT(integrate(0.5).coveredArea, 0.0);
  }
}

// An open surface inclined across the slave spreads its gaps over more than the slave's size:
// it is one surface, every part of it counts (only surfaces behind the nearest are dropped).
TEST(MortarMasterSelection, AnInclinedSurfaceInFrontCoversTheWholeSlave) {
  const Facet slave = makeFacet(ElementType::Quad4, unitSlave(ElementType::Quad4));
  // The plane z = h tilted by 70 degrees about x through the slave's centre: 2 in front of it
  // there (h = 2 cos 70), gaps 0.63 to 3.37 over the slave.
  const double tilt = 70 * kPi / 180;
  const std::vector<Facet> masters =
      masterGrid(ElementType::Quad4, 8, -3.0, 4.0, 0.0, 2 * std::cos(tilt), {1, 0, 0}, tilt);
  const MortarIntegrals r =
      integrateMortar(slave, nodeNormals(slave), pointers(masters), MultiplierBasis::Dual);
  EXPECT_NEAR(r.coveredArea, r.area, 1e-12);
}

}  // namespace
}  // namespace contactlab
