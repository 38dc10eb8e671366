// The pressure field of nodal forces on quadratic facets (SurfacePressure.hpp): the consistent
// nodal forces of a uniform or linear field give that field back at every node, and an error in
// a corner's force moves the field by about that error over the corner's hat integral, not
// over the corner's ~0 tri6 integral.
#include "core/contact/SurfacePressure.hpp"
#include "core/fem/QuadratureRule.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <algorithm>
#include <cmath>
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

// f_i = int p N_i dA over the two facets, p(x, y) = 2 + 3 x - y, by a degree-5 rule.
std::map<std::int64_t, double> consistentForces(const Mesh& m, double (*p)(double, double)) {
  const CellGroup& g = m.boundaries[0];
  const ReferenceElement& ref = ReferenceElement::get(ElementType::Tri6);
  const QuadratureRule& rule = quadratureRule(ElementType::Tri6, 5);
  std::map<std::int64_t, double> f;
  double N[6];
  for (std::size_t c = 0; c < g.size(); ++c) {
    const std::int64_t* nodes = &g.nodes[c * 6];
    for (int q = 0; q < rule.size(); ++q) {
      ref.shape(&rule.points[q * rule.dim], N);
      double x = 0, y = 0;
      for (int a = 0; a < 6; ++a) {
        x += N[a] * m.coords[3 * nodes[a]];
        y += N[a] * m.coords[3 * nodes[a] + 1];
      }
      // Both facets are right triangles of area 1/2: dA = 2 A w = w (weights sum to 1/2).
      for (int a = 0; a < 6; ++a)
        f[nodes[a]] += p(x, y) * N[a] * rule.weights[q];
    }
  }
  return f;
}

double linearField(double x, double y) {
  return 2 + 3 * x - y;
}

TEST(SurfacePressure, ConsistentForcesOfALinearPressureGiveItBackAtEveryNode) {
  const Mesh m = twoTri6();
  const auto p = pressureFromNodalForces(m, "face", consistentForces(m, linearField));
  ASSERT_EQ(p.size(), 9u);
  for (const auto& [node, value] : p)
    EXPECT_NEAR(value, linearField(m.coords[3 * node], m.coords[3 * node + 1]), 1e-10)
        << "node " << node;
}

// The node-to-segment reactions at tri6 corners are short of the consistent loads by a small
// amount (doc/verification.md): the field must not amplify it more than need be. Corner 1 (one
// facet, hat integral A / 3 = 1/6) gets an error of 1e-3: the linear field moves by 0.015 at
// most, the quadratic projection (M p = f with the tri6 mass, whose corner integrals are 0)
// moved it by 0.066 (measured on this patch).
TEST(SurfacePressure, AnErrorInACornerForceIsNotAmplified) {
  const Mesh m = twoTri6();
  auto f = consistentForces(m, linearField);
  f[1] += 1e-3;
  double largest = 0;
  for (const auto& [node, value] : pressureFromNodalForces(m, "face", f))
    largest = std::max(largest,
                       std::abs(value - linearField(m.coords[3 * node], m.coords[3 * node + 1])));
  EXPECT_LT(largest, 0.03);
  EXPECT_GT(largest, 1e-3);  // it does move the field
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
