// MeshCache: a mesh met again under its key is a copy of the kept one (a run's own point groups
// do not leak into the next run's), built once; an exception from the build keeps nothing; the
// least recently used mesh is dropped past the capacity.
#include "apps/MeshCache.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace contactlab {
namespace {

std::shared_ptr<Mesh> oneNodeMesh(double x) {
  auto mesh = std::make_shared<Mesh>();
  mesh->dim = 2;
  mesh->coords = {x, 0.0, 0.0};
  return mesh;
}

TEST(MeshCache, AKeyMetAgainGetsACopyOfTheMeshBuiltOnce) {
  MeshCache cache;
  int built = 0;
  const auto build = [&] {
    ++built;
    return oneNodeMesh(1.0);
  };
  auto first = cache.meshFor("rectangle nx=2", build);
  first->boundaries.push_back(CellGroup{});  // a run's point group, on its own copy
  auto second = cache.meshFor("rectangle nx=2", build);
  EXPECT_EQ(built, 1);
  EXPECT_EQ(cache.builds(), 1);
  EXPECT_NE(first.get(), second.get());
  EXPECT_TRUE(second->boundaries.empty());
  EXPECT_EQ(second->coords, first->coords);
  cache.meshFor("rectangle nx=4", build);
  EXPECT_EQ(built, 2);
}

TEST(MeshCache, AFailedBuildKeepsNothing) {
  MeshCache cache;
  EXPECT_THROW(
      cache.meshFor("bad",
                    []() -> std::shared_ptr<Mesh> { throw std::runtime_error("gmsh failed"); }),
      std::runtime_error);
  EXPECT_EQ(cache.size(), 0u);
  EXPECT_EQ(cache.meshFor("bad", [] { return oneNodeMesh(2.0); })->coords[0], 2.0);
}

TEST(MeshCache, TheLeastRecentlyUsedIsDroppedPastTheCapacity) {
  MeshCache cache(2);
  cache.meshFor("a", [] { return oneNodeMesh(1.0); });
  cache.meshFor("b", [] { return oneNodeMesh(2.0); });
  cache.meshFor("a", [] { return oneNodeMesh(-1.0); });  // kept: a is now the newest
  cache.meshFor("c", [] { return oneNodeMesh(3.0); });   // b is dropped
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_EQ(cache.meshFor("a", [] { return oneNodeMesh(-1.0); })->coords[0], 1.0);
  EXPECT_EQ(cache.meshFor("b", [] { return oneNodeMesh(-2.0); })->coords[0], -2.0);
  EXPECT_EQ(cache.builds(), 4);
}

}  // namespace
}  // namespace contactlab
