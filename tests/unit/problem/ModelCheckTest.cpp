// The problem refuses a broken model before anything runs, with one sentence naming the culprit.
#include "ProblemTestSupport.hpp"

#include "base/InputError.hpp"

#include <gtest/gtest.h>

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
  model.materials["steel"] = model.materials["body"];
  model.materials.erase("body");
  const std::string m = messageOf(model);
  EXPECT_NE(m.find("block 'body'"), std::string::npos) << m;
  EXPECT_NE(m.find("no material"), std::string::npos) << m;
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

TEST(ModelCheck, LinearElasticRejectsBadConstants) {
  EXPECT_THROW(LinearElastic(0.0, 0.3), std::invalid_argument);
  EXPECT_THROW(LinearElastic(1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(LinearElastic(1.0, -1.0), std::invalid_argument);
  EXPECT_NO_THROW(LinearElastic(1.0, 0.4999));
}

}  // namespace
}  // namespace contactlab::test
