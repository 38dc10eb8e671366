// The blade-root generator: two disjoint valid bodies whose contact flanks coincide, the named
// groups where the parameters put them, the areas of the straight-edged outline, and refusals
// that name the parameter.
#include "tests/unit/mesh/MeshTestUtils.hpp"

#include "core/mesh/BladeRootProfile.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

double shoelace(const std::vector<BladeRootProfile::Point>& v) {
  double a = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const auto& p = v[i];
    const auto& q = v[(i + 1) % v.size()];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * a;
}

class BladeRootGenerator : public ::testing::TestWithParam<std::tuple<int, std::string>> {};

TEST_P(BladeRootGenerator, TwoBodiesTouchingOnTheFlanks) {
  BladeRootParams p;
  p.lobes = std::get<0>(GetParam());
  p.elementType = std::get<1>(GetParam());
  p.sizeFar = 4.0;
  const Mesh mesh = generateBladeRoot(p);
  const BladeRootProfile profile(p);
  EXPECT_GT(test::minJacobian(mesh), 0.0);
  const auto blade = test::blockNodes(mesh, "blade"), disc = test::blockNodes(mesh, "disc");
  for (auto n : blade)
    EXPECT_EQ(disc.count(n), 0u) << "node " << n << " is shared by the two bodies";
  // Both bodies' flank nodes lie on the same segments (zero initial gap), or on the fillets at
  // their ends, within two fillet radii of them (an arc reaches 2 r sin^2(turn / 2) off its line).
  for (const char* group : {"blade-flanks", "disc-flanks"}) {
    std::size_t onSegments = 0;
    for (auto n : mesh.boundaryNodes(group)) {
      const auto x = test::node(mesh, n);
      const double d = profile.flankDistance(x[0], x[1]);
      EXPECT_LT(d, 2 * p.filletRadius) << group << " node " << n;
      if (d < 1e-9) ++onSegments;
    }
    EXPECT_GE(onSegments, 2u * profile.flanks().size()) << group;
  }
  const double half = 0.5 * p.sectorAngle * M_PI / 180;
  for (auto n : mesh.boundaryNodes("disc-inner")) {
    const auto x = test::node(mesh, n);
    EXPECT_NEAR(std::hypot(x[0], x[1]), p.innerRadius, 1e-9);
  }
  for (auto n : mesh.boundaryNodes("disc-sides")) {
    const auto x = test::node(mesh, n);
    EXPECT_NEAR(std::abs(std::atan2(x[0], x[1])), half, 1e-9);
  }
  for (auto n : mesh.boundaryNodes("blade-top"))
    EXPECT_NEAR(test::node(mesh, n)[1], p.outerRadius + p.bladeHeight, 1e-9);
  for (const char* group : {"blade-free", "disc-slot", "disc-outer"})
    EXPECT_FALSE(mesh.boundaryNodes(group).empty()) << group;
}

INSTANTIATE_TEST_SUITE_P(LobesAndTypes, BladeRootGenerator,
                         ::testing::Combine(::testing::Values(2, 3),
                                            ::testing::Values("tri3", "quad4", "quad8")));

TEST(BladeRootGenerator, HexElementsSweepTheSectionAlongZ) {
  for (const char* type : {"hex8", "hex20"}) {
    BladeRootParams p;
    p.elementType = type;
    p.sizeFar = 4.0;
    p.thickness = 6.0;
    p.layers = 3;
    const Mesh mesh = generateBladeRoot(p);
    const BladeRootProfile profile(p);
    ASSERT_EQ(mesh.dim, 3) << type;
    EXPECT_GT(test::minJacobian(mesh), 0.0) << type;
    const auto blade = test::blockNodes(mesh, "blade"), disc = test::blockNodes(mesh, "disc");
    for (auto n : blade)
      EXPECT_EQ(disc.count(n), 0u) << type << ": node " << n << " is shared by the two bodies";
    for (const char* group : {"blade-flanks", "disc-flanks"}) {
      std::size_t onSegments = 0;
      for (auto n : mesh.boundaryNodes(group)) {
        const auto x = test::node(mesh, n);
        const double d = profile.flankDistance(x[0], x[1]);
        EXPECT_LT(d, 2 * p.filletRadius) << type << " " << group << " node " << n;
        if (d < 1e-9) ++onSegments;
      }
      EXPECT_GE(onSegments, 2u * profile.flanks().size() * (p.layers + 1)) << type << group;
    }
    for (auto n : mesh.boundaryNodes("disc-inner")) {
      const auto x = test::node(mesh, n);
      EXPECT_NEAR(std::hypot(x[0], x[1]), p.innerRadius, 1e-9) << type;
    }
    for (const auto& [group, z] : {std::pair<const char*, double>{"blade-back", 0.0},
                                   {"disc-back", 0.0},
                                   {"blade-front", 6.0},
                                   {"disc-front", 6.0}})
      for (auto n : mesh.boundaryNodes(group))
        EXPECT_NEAR(test::node(mesh, n)[2], z, 1e-9) << type << " " << group;
    // The swept blade is its section's area times the thickness.
    BladeRootParams section = p;
    section.elementType = "quad4";
    EXPECT_NEAR(test::blockMeasure(mesh, "blade"),
                6.0 * test::blockMeasure(generateBladeRoot(section), "blade"), 1e-3)
        << type;
  }
}

TEST(BladeRootGenerator, SharpOutlineHasThePolygonsAreas) {
  // Without fillets every edge of root and slot is straight: the blade's area is its polygon's,
  // the disc's the sector's minus the slot (its polygon closed by the chord between the mouths,
  // clockwise, plus the circular segment over that chord), up to the chords of the meshed outer and
  // inner arcs.
  BladeRootParams p;
  p.filletRadius = 0.0;
  p.sizeFar = 1.0;
  const Mesh mesh = generateBladeRoot(p);
  const BladeRootProfile profile(p);
  EXPECT_NEAR(test::blockMeasure(mesh, "blade"), shoelace(profile.blade()), 1e-9);
  const double mouth = profile.slot().front()[0];
  const double chordAngle = 2 * std::asin(mouth / p.outerRadius);
  const double slot = std::abs(shoelace(profile.slot())) +
                      0.5 * p.outerRadius * p.outerRadius * (chordAngle - std::sin(chordAngle));
  const double sector = 0.5 * p.sectorAngle * M_PI / 180 *
                        (p.outerRadius * p.outerRadius - p.innerRadius * p.innerRadius);
  EXPECT_NEAR(test::blockMeasure(mesh, "disc"), sector - slot, 1e-4 * sector);
}

TEST(BladeRootGenerator, RefusesDegenerateRoots) {
  const auto refused = [](auto change, const std::string& parameter) {
    BladeRootParams p;
    change(p);
    try {
      generateBladeRoot(p);
      ADD_FAILURE() << parameter << ": accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(parameter), std::string::npos) << e.what();
    }
  };
  refused([](BladeRootParams& p) { p.lobes = 5; }, "Lobes");
  refused([](BladeRootParams& p) { p.lobePitch = 2.0; }, "Lobe Pitch");
  refused([](BladeRootParams& p) { p.taper = 3.0; }, "Taper");
  refused([](BladeRootParams& p) { p.flankAngle = 80.0; }, "Flank Angle");
  refused([](BladeRootParams& p) { p.innerRadius = 85.0; }, "inner radius");
  refused([](BladeRootParams& p) { p.sectorAngle = 8.0; }, "Sector Angle");
  refused([](BladeRootParams& p) { p.filletRadius = 3.0; }, "Fillet Radius");
  refused([](BladeRootParams& p) { p.elementType = "tet4"; }, "element type");
}

}  // namespace
}  // namespace contactlab
