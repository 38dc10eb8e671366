#include "tests/unit/fem/FemTestSupport.hpp"

#include "core/problem/MassKernel.hpp"
#include "core/problem/SmallStrainKernel.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

using test::nameOf;

// Volume with a rule far above what any element needs: the reference for the mass' total.
double exactVolume(ElementType t, const std::vector<double>& x) {
  return SmallStrainKernel(t, 8).volume(x.data());
}

TEST(MassKernel, ConsistentMassIsSymmetricPerComponentAndHoldsTheElementMass) {
  const double rho = 2.5;
  for (ElementType t : test::solidTypes()) {
    const MassKernel kernel(t);
    const auto x = test::distortedNodes(t);
    const int nd = kernel.numDofs(), d = info(t).dim;
    std::vector<double> m(nd * nd, 0.0);
    kernel.add(x.data(), rho, false, m.data());
    const double mass = rho * exactVolume(t, x);
    for (int i = 0; i < d; ++i) {
      double total = 0;
      for (int a = 0; a < nd; a += d)
        for (int b = 0; b < nd; b += d)
          total += m[(a + i) * nd + b + i];
      EXPECT_NEAR(total, mass, 1e-12 * mass) << nameOf(t) << " component " << i;
    }
    for (int r = 0; r < nd; ++r)
      for (int c = 0; c < nd; ++c) {
        EXPECT_NEAR(m[r * nd + c], m[c * nd + r], 1e-14 * mass) << nameOf(t);
        if (r % d != c % d) {
          EXPECT_EQ(m[r * nd + c], 0.0) << nameOf(t) << " couples components";
        }
      }
  }
}

TEST(MassKernel, LumpedMassIsPositiveDiagonalWithTheSameTotal) {
  for (ElementType t : test::solidTypes()) {
    const MassKernel kernel(t);
    const auto x = test::distortedNodes(t);
    const int nd = kernel.numDofs();
    std::vector<double> m(nd * nd, 0.0);
    kernel.add(x.data(), 1.0, true, m.data());
    double total = 0;
    for (int r = 0; r < nd; ++r)
      for (int c = 0; c < nd; ++c) {
        if (r == c) {
          EXPECT_GT(m[r * nd + r], 0.0) << nameOf(t) << " dof " << r;
          total += m[r * nd + r];
        } else {
          EXPECT_EQ(m[r * nd + c], 0.0) << nameOf(t);
        }
      }
    const double mass = exactVolume(t, x) * info(t).dim;
    EXPECT_NEAR(total, mass, 1e-12 * mass) << nameOf(t);
  }
}

TEST(MassKernel, AddsToWhatIsThere) {
  const MassKernel kernel(ElementType::Quad4);
  const auto x = test::distortedNodes(ElementType::Quad4);
  std::vector<double> once(64, 0.0), twice(64, 0.0);
  kernel.add(x.data(), 1.0, false, once.data());
  kernel.add(x.data(), 1.0, false, twice.data());
  kernel.add(x.data(), 1.0, false, twice.data());
  for (int k = 0; k < 64; ++k)
    EXPECT_DOUBLE_EQ(twice[k], 2 * once[k]);
}

}  // namespace
}  // namespace contactlab
