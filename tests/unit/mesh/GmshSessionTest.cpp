#include "core/mesh/GmshSession.hpp"
#include "core/mesh/MeshGenerators.hpp"

#include <gmsh.h>

#include <gtest/gtest.h>

namespace contactlab {
namespace {

TEST(GmshSession, NestsAndFinalisesWithTheOutermost) {
  EXPECT_FALSE(GmshSession::active());
  {
    GmshSession outer;
    {
      GmshSession inner;
      EXPECT_TRUE(GmshSession::active());
    }
    EXPECT_TRUE(GmshSession::active());
    double terminal = 1;
    gmsh::option::getNumber("General.Terminal", terminal);
    EXPECT_EQ(terminal, 0.0);  // quiet
  }
  EXPECT_FALSE(GmshSession::active());
}

TEST(GmshSession, GeneratorsLeaveTheCallersModelAlone) {
  GmshSession session;
  gmsh::model::add("mine");
  gmsh::model::occ::addPoint(1, 2, 3);
  gmsh::model::occ::synchronize();
  RectangleParams p;
  p.divisions = {2, 2};
  const Mesh mesh = generateRectangle(p);
  EXPECT_EQ(mesh.numNodes(), 9u);
  std::string current;
  gmsh::model::getCurrent(current);
  EXPECT_EQ(current, "mine");
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities);
  EXPECT_EQ(entities.size(), 1u);
  gmsh::model::remove();
}

TEST(GmshSession, GmshCanBeRestartedAfterFinalize) {
  RectangleParams p;
  EXPECT_EQ(generateRectangle(p).numNodes(), 4u);
  EXPECT_FALSE(GmshSession::active());
  EXPECT_EQ(generateRectangle(p).numNodes(), 4u);
}

}  // namespace
}  // namespace contactlab
