#include "tests/unit/fem/FemTestSupport.hpp"

#include "core/fem/ReferenceElement.hpp"

#include <gtest/gtest.h>

namespace contactlab {
namespace {

using test::allTypes;
using test::nameOf;

TEST(ReferenceElement, SizesMatchElementTypeInfo) {
  for (ElementType t : allTypes()) {
    const auto& ref = ReferenceElement::get(t);
    EXPECT_EQ(ref.type(), t);
    EXPECT_EQ(ref.dim(), info(t).dim) << nameOf(t);
    EXPECT_EQ(ref.numNodes(), info(t).nodes) << nameOf(t);
    EXPECT_EQ(ref.nodeCoordinates().size(), std::size_t(info(t).dim * info(t).nodes)) << nameOf(t);
    EXPECT_EQ(&ReferenceElement::get(t), &ref);
  }
}

TEST(ReferenceElement, PartitionOfUnity) {
  std::mt19937 rng(1);
  for (ElementType t : allTypes()) {
    const auto& ref = ReferenceElement::get(t);
    const int n = ref.numNodes(), d = ref.dim();
    std::vector<double> N(n), dN(n * d);
    for (int trial = 0; trial < 10; ++trial) {
      const auto xi = test::randomPoint(t, rng);
      ref.shape(xi.data(), N.data());
      ref.shapeDerivatives(xi.data(), dN.data());
      double sum = 0;
      for (double v : N)
        sum += v;
      EXPECT_NEAR(sum, 1.0, 1e-14) << nameOf(t);
      for (int i = 0; i < d; ++i) {
        double dsum = 0;
        for (int a = 0; a < n; ++a)
          dsum += dN[a * d + i];
        EXPECT_NEAR(dsum, 0.0, 1e-13) << nameOf(t);
      }
    }
  }
}

TEST(ReferenceElement, KroneckerAtNodes) {
  for (ElementType t : allTypes()) {
    const auto& ref = ReferenceElement::get(t);
    const int n = ref.numNodes(), d = ref.dim();
    std::vector<double> N(n);
    for (int b = 0; b < n; ++b) {
      ref.shape(&ref.nodeCoordinates()[b * d], N.data());
      for (int a = 0; a < n; ++a)
        EXPECT_NEAR(N[a], a == b ? 1.0 : 0.0, 1e-15)
            << nameOf(t) << " N_" << a << "(x_" << b << ")";
    }
  }
}

TEST(ReferenceElement, DerivativesMatchCentralDifferences) {
  std::mt19937 rng(2);
  const double h = 1e-6;
  for (ElementType t : allTypes()) {
    const auto& ref = ReferenceElement::get(t);
    const int n = ref.numNodes(), d = ref.dim();
    std::vector<double> dN(n * d), Np(n), Nm(n);
    for (int trial = 0; trial < 5; ++trial) {
      const auto xi = test::randomPoint(t, rng);
      ref.shapeDerivatives(xi.data(), dN.data());
      for (int i = 0; i < d; ++i) {
        auto xp = xi, xm = xi;
        xp[i] += h, xm[i] -= h;
        ref.shape(xp.data(), Np.data());
        ref.shape(xm.data(), Nm.data());
        for (int a = 0; a < n; ++a)
          EXPECT_NEAR(dN[a * d + i], (Np[a] - Nm[a]) / (2 * h), 1e-8)
              << nameOf(t) << " a=" << a << " i=" << i;
      }
    }
  }
}

// Lagrange elements reproduce every polynomial of their space: the coordinates themselves
// (isoparametric) and, for the quadratic ones, the products the space contains.
TEST(ReferenceElement, ReproducesLinearFields) {
  std::mt19937 rng(3);
  for (ElementType t : allTypes()) {
    const auto& ref = ReferenceElement::get(t);
    const int n = ref.numNodes(), d = ref.dim();
    std::vector<double> N(n);
    for (int trial = 0; trial < 5; ++trial) {
      const auto xi = test::randomPoint(t, rng);
      ref.shape(xi.data(), N.data());
      for (int i = 0; i < d; ++i) {
        double v = 0;
        for (int a = 0; a < n; ++a)
          v += N[a] * ref.nodeCoordinates()[a * d + i];
        EXPECT_NEAR(v, xi[i], 1e-14) << nameOf(t);
      }
    }
  }
}

TEST(ReferenceElement, SerendipityCentreValues) {
  // Serendipity, not Lagrange: at the centre corners take -1/4 (quad8) and -1/4 (hex20),
  // mid-edge nodes 1/2 (quad8) and 1/4 (hex20).
  std::vector<double> N(20);
  const double centre[3] = {0, 0, 0};
  ReferenceElement::get(ElementType::Quad8).shape(centre, N.data());
  for (int a = 0; a < 4; ++a)
    EXPECT_NEAR(N[a], -0.25, 1e-15);
  for (int a = 4; a < 8; ++a)
    EXPECT_NEAR(N[a], 0.5, 1e-15);
  ReferenceElement::get(ElementType::Hex20).shape(centre, N.data());
  for (int a = 0; a < 8; ++a)
    EXPECT_NEAR(N[a], -0.25, 1e-15);
  for (int a = 8; a < 20; ++a)
    EXPECT_NEAR(N[a], 0.25, 1e-15);
}

}  // namespace
}  // namespace contactlab
