// The problem refuses a broken model before anything runs, with one sentence naming the culprit.
#include "ProblemTestSupport.hpp"

#include "base/InputError.hpp"
#include "core/materials/NeoHookean.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <memory>
#include <optional>

namespace contactlab::test {
namespace {

Field zero = [](const double*, double* u) { u[0] = u[1] = u[2] = 0; };

std::string messageOf(const SolidModel& model) {
  try {
    Problem problem(model, Tpetra::getDefaultComm());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ModelCheck, InvertedElementIsNamed) {
  auto mesh = unitMesh("quad4", 2);
  // Swap two nodes of cell 3: its orientation flips.
  auto& nodes = mesh->blocks[0].nodes;
  std::swap(nodes[3 * 4 + 1], nodes[3 * 4 + 3]);
  const std::string m = messageOf(elasticModel(mesh, 1.0, 0.3, zero, {}));
  EXPECT_NE(m.find("inverted"), std::string::npos) << m;
  EXPECT_NE(m.find("element 3 "), std::string::npos) << m;
  EXPECT_NE(m.find("block 'body'"), std::string::npos) << m;
}

TEST(ModelCheck, MissingBoundaryGroupListsTheKnownOnes) {
  auto model = elasticModel(unitMesh("tri3", 2), 1.0, 0.3, zero, {});
  model.dirichlet[0].group = "bottm";
  const std::string m = messageOf(model);
  EXPECT_NE(m.find("'bottm'"), std::string::npos) << m;
  EXPECT_NE(m.find("bottom"), std::string::npos) << m;
}

TEST(ModelCheck, BlockWithoutMaterial) {
  auto model = elasticModel(unitMesh("tri3", 2), 1.0, 0.3, zero, {});
  model.materials.erase("body");
  const std::string m = messageOf(model);
  EXPECT_NE(m.find("block 'body'"), std::string::npos) << m;
  EXPECT_NE(m.find("no material"), std::string::npos) << m;
}

// A material under a name no block has is named first (the likely slip: its block then has
// none), with the mesh's blocks.
TEST(ModelCheck, MaterialForNoBlock) {
  auto model = elasticModel(unitMesh("tri3", 2), 1.0, 0.3, zero, {});
  model.materials["steel"] = model.materials["body"];
  model.materials.erase("body");
  const std::string m = messageOf(model);
  EXPECT_NE(m.find("material given for block 'steel'"), std::string::npos) << m;
  EXPECT_NE(m.find("its blocks are: body"), std::string::npos) << m;
}

TEST(ModelCheck, SmallStrainBlocksKeepTheDeadPressureAndRefuseAFollower) {
  auto model = elasticModel(unitMesh("quad4", 2), 1.0, 0.3, zero, {});
  model.dirichlet.pop_back();
  SurfaceLoad load;
  load.name = "p";
  load.group = "top";
  load.pressure = 1.0;
  model.surfaceLoads.push_back(load);
  EXPECT_TRUE(Problem(model, Tpetra::getDefaultComm()).followerLoads().empty());
  model.surfaceLoads[0].follower = SurfaceLoad::Follower::Yes;
  const std::string m = messageOf(model);
  EXPECT_NE(m.find("load 'p'"), std::string::npos) << m;
  EXPECT_NE(m.find("Follower: true"), std::string::npos) << m;
  EXPECT_NE(m.find("block 'body'"), std::string::npos) << m;
  EXPECT_NE(m.find("small-strain"), std::string::npos) << m;
}

// A plane-stress model has no follower pressure (the facets' current area needs the plate's
// current thickness); a traction is a dead load, so a finite-strain model with one is not
// refused (it was, as a 'follower pressure', with advice to set a Follower option that a
// traction does not take). An axisymmetric model takes both (the follower pressure on the
// current ring: FollowerPressureTest).
TEST(ModelCheck, PlaneStressModelsRefuseFollowerPressuresOnly) {
  auto model = elasticModel(unitMesh("quad4", 2), 1.0, 0.3, zero, {});
  model.dirichlet.pop_back();
  model.materials["body"] = std::make_shared<NeoHookean>(0.2, 1.0);
  SurfaceLoad traction;
  traction.name = "t";
  traction.group = "top";
  traction.kind = SurfaceLoad::Kind::Traction;
  traction.traction = {0.0, 1.0, 0.0};
  model.surfaceLoads.push_back(traction);
  SolidModel pressed = model;
  SurfaceLoad pressure;
  pressure.name = "p";
  pressure.group = "top";
  pressure.pressure = 1.0;
  pressed.surfaceLoads.push_back(pressure);
  for (bool axisymmetric : {true, false}) {
    model.axisymmetric = pressed.axisymmetric = axisymmetric;
    model.planeStress = pressed.planeStress = !axisymmetric;
    EXPECT_EQ(messageOf(model), "") << axisymmetric;
    const std::string m = messageOf(pressed);
    if (axisymmetric) {
      EXPECT_EQ(m, "");
      continue;
    }
    EXPECT_NE(m.find("load 'p'"), std::string::npos) << m;
    EXPECT_NE(m.find("no follower pressure"), std::string::npos) << m;
    pressed.surfaceLoads.back().follower = SurfaceLoad::Follower::No;
    EXPECT_EQ(messageOf(pressed), "") << axisymmetric;
    pressed.surfaceLoads.back().follower = SurfaceLoad::Follower::Automatic;
  }
}

TEST(ModelCheck, LinearElasticRejectsBadConstants) {
  EXPECT_THROW(LinearElastic(0.0, 0.3), std::invalid_argument);
  EXPECT_THROW(LinearElastic(1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(LinearElastic(1.0, -1.0), std::invalid_argument);
  EXPECT_NO_THROW(LinearElastic(1.0, 0.4999));
}

// A law that takes no temperature (every registered one does; a plug-in law need not).
class Isothermal : public LinearElastic {
 public:
  using LinearElastic::LinearElastic;
  std::optional<double> referenceTemperature() const override { return std::nullopt; }
};

TEST(ModelCheck, BlockTemperaturesNameAHeatableBlockOnce) {
  auto model = elasticModel(unitMesh("quad4", 2), 1.0, 0.3, zero, {});
  BlockTemperature heating;
  heating.block = "steel";
  heating.value = 304.0;
  model.temperatures = {heating};
  std::string m = messageOf(model);
  EXPECT_NE(m.find("temperature given for block 'steel', which has no material"), std::string::npos)
      << m;
  model.temperatures[0].block = "body";
  model.temperatures.push_back(model.temperatures[0]);
  m = messageOf(model);
  EXPECT_NE(m.find("two temperatures given for block 'body'"), std::string::npos) << m;
  model.temperatures.pop_back();
  model.materials["body"] = std::make_shared<Isothermal>(1.0, 0.3);
  m = messageOf(model);
  EXPECT_NE(m.find("material linear-elastic takes no temperature"), std::string::npos) << m;
}

// A clamped plane-strain square at u = 0, heated on a ramp from T_ref = 20 to 304 degC over
// [0, 1]: the stress the outputs report at time t is the fully held one at T(t),
// -E alpha (T(t) - T_ref) / (1 - 2 nu) in xx, yy and zz; the same square without the entry is
// stress-free at any t.
TEST(ModelCheck, BlockTemperatureIsEvaluatedAtTheOutputTime) {
  const double E = 200e3, nu = 0.3, alpha = 1.4e-5;
  auto model = elasticModel(unitMesh("quad4", 2), E, nu, zero, {});
  LinearElastic::Parameters steel;
  steel.youngModulus = E;
  steel.poissonRatio = nu;
  steel.expansion.coefficient = alpha;
  model.materials["body"] = std::make_shared<LinearElastic>(steel);
  const SolidModel cold = model;
  BlockTemperature heating;
  heating.block = "body";
  heating.value = 304.0;
  model.temperatures = {heating};
  const Problem problem(model, Tpetra::getDefaultComm()), reference(cold, Tpetra::getDefaultComm());
  auto u = problem.createVector();
  u->putScalar(0.0);
  const std::int64_t centre = model.mesh->numNodes() / 2;
  for (double t : {0.0, 0.5, 1.0, 2.0}) {
    const double dT = 284.0 * std::min(t, 1.0);
    const auto s = problem.nodeStress(*u, centre, t);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(s[k], -E * alpha * dT / (1 - 2 * nu), 1e-9) << "t = " << t << " " << k;
    EXPECT_EQ(problem.blockTemperature(0, t), std::optional<double>(20.0 + dT));
    for (double c : reference.nodeStress(*u, centre, t))
      EXPECT_EQ(c, 0.0);
  }
  EXPECT_EQ(reference.blockTemperature(0, 1.0), std::nullopt);
}

}  // namespace
}  // namespace contactlab::test
