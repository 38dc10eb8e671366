// The pressure field of nodal forces on quadratic facets (SurfacePressure.hpp): the consistent
// nodal forces of a field give that field back, and f / w does not on tri6.
#include "core/contact/SurfacePressure.hpp"

#include <gtest/gtest.h>

namespace contactlab {
namespace {

// Two tri6 facets covering the unit square z = 0 (corners 0..3, mid-edge nodes 4..8).
Mesh twoTri6() {
  Mesh m;
  m.dim = 3;
  m.coords = {0,   0, 0, 1, 0,   0, 1,   1,   0, 0, 1,   0,              // corners
              0.5, 0, 0, 1, 0.5, 0, 0.5, 0.5, 0, 0, 0.5, 0, 0.5, 1, 0};  // mids
  CellGroup g;
  g.name = "face";
  g.dim = 2;
  g.type = ElementType::Tri6;
  // (0, 1, 2): mids 0-1 = 4, 1-2 = 5, 2-0 = 6; (0, 2, 3): mids 0-2 = 6, 2-3 = 8, 3-0 = 7.
  g.nodes = {0, 1, 2, 4, 5, 6, 0, 2, 3, 6, 8, 7};
  g.tags = {1, 2};
  m.boundaries.push_back(g);
  return m;
}

TEST(SurfacePressure, ConsistentForcesOfAUniformPressureGiveItBack) {
  const Mesh m = twoTri6();
  // int N_i over a tri6 of area A: 0 at corners, A / 3 at mid-edge nodes (A = 1/2 each).
  const double p = 3.5, third = 0.5 / 3;
  std::map<std::int64_t, double> f{{0, 0},
                                   {1, 0},
                                   {2, 0},
                                   {3, 0},
                                   {4, third * p},
                                   {5, third * p},
                                   {6, 2 * third * p},
                                   {7, third * p},
                                   {8, third * p}};
  for (const auto& [node, value] : pressureFromNodalForces(m, "face", f))
    EXPECT_NEAR(value, p, 1e-10) << "node " << node;
}

TEST(SurfacePressure, NoForceNoPressure) {
  std::map<std::int64_t, double> none;
  for (std::int64_t n = 0; n < 9; ++n)
    none[n] = 0;
  for (const auto& [node, value] : pressureFromNodalForces(twoTri6(), "face", none))
    EXPECT_EQ(value, 0.0) << "node " << node;
}

}  // namespace
}  // namespace contactlab
