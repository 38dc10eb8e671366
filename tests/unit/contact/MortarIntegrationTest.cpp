// Mortar integrals D and M of one slave facet against master facets: identities that hold to
// round-off (matching facets give the mass matrix, the patch property sum_l M_jl = sum_k D_jk,
// exact transfer of linear fields between coplanar facets, biorthogonality of the dual basis).
// Coverage of known areas is MortarCoverageTest.cpp.
#include "tests/unit/contact/MortarTestSupport.hpp"

#include "core/contact/MortarIntegration.hpp"
#include "core/fem/ReferenceElement.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace contactlab {
namespace {

using namespace test;

// ---- 1. Matching facets ----

// D = T M_e, T the multiplier basis transform (the identity but on tri6/quad8).
TEST(MortarIntegration, IdenticalFacetsGiveTheConsistentMassMatrix) {
  for (ElementType t : kFacetTypes) {
    const auto& [slave, masters, r, exact, T, n] = matchingFacets(t, MultiplierBasis::Standard);
    ASSERT_EQ(r.masters.size(), 1u);
    EXPECT_NEAR(r.area, exact.area, 1e-14);
    EXPECT_NEAR(r.coveredArea, exact.area, 1e-14) << info(t).name;
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        double transformed = 0.0;
        for (int m = 0; m < n; ++m)
          transformed += T[j * n + m] * exact.mass[m * n + k];
        EXPECT_NEAR(r.D[j * n + k], transformed, 1e-15) << info(t).name;
        // The master node at slave node k's position.
        int l = 0;
        while (std::hypot(masters[0].coords[3 * l] - slave.coords[3 * k],
                          masters[0].coords[3 * l + 1] - slave.coords[3 * k + 1],
                          masters[0].coords[3 * l + 2] - slave.coords[3 * k + 2]) > 1e-12)
          ++l;
        EXPECT_NEAR(r.masters[0].M[j * n + l], r.D[j * n + k], 1e-15) << info(t).name;
      }
  }
}

// ---- 2. and 3. Patch property and linear fields on non-matching facets ----
TEST(MortarIntegration, PatchPropertyOnNonMatchingMasters) {
  forEachPatchCase(
      [](const Facet& slave, const std::vector<Facet>& masters, const MortarIntegrals& r) {
        EXPECT_GE(r.masters.size(), 3u);
        EXPECT_NEAR(r.coveredArea, r.area, 1e-13 * r.area);
        expectTransfer(slave, masters, r, constantField, 1e-13 * r.area);
      });
}

TEST(MortarIntegration, LinearFieldsTransferExactlyBetweenCoplanarFacets) {
  forEachPatchCase(
      [](const Facet& slave, const std::vector<Facet>& masters, const MortarIntegrals& r) {
        expectTransfer(slave, masters, r, linearField, 1e-12 * r.area);
      });
}

// ---- 4. Dual basis ----

// Biorthogonal to the transformed functions T N (T the identity but on tri6/quad8):
// int Phi_j (T N)_k = (D T^T)_jk = delta_jk int (T N)_j.
TEST(MortarIntegration, DualBasisIsBiorthogonal) {
  for (ElementType t : kFacetTypes) {
    const auto& [slave, masters, r, exact, T, n] = matchingFacets(t, MultiplierBasis::Dual);
    const std::vector<double> B = dualBasisCoefficients(slave);
    for (int j = 0; j < n; ++j) {
      double integral = 0.0, transformed = 0.0;  // int Phi_j dA, int (T N)_j dA
      for (int k = 0; k < n; ++k) {
        integral += B[j * n + k] * exact.lumped[k];
        transformed += T[j * n + k] * exact.lumped[k];
      }
      EXPECT_GT(transformed, 0.0) << info(t).name;
      EXPECT_NEAR(integral, transformed, 1e-14) << info(t).name;
      for (int k = 0; k < n; ++k) {
        double against = 0.0;
        for (int m = 0; m < n; ++m)
          against += r.D[j * n + m] * T[k * n + m];
        EXPECT_NEAR(against, j == k ? transformed : 0.0, 1e-14) << info(t).name;
      }
    }
  }
}

// tri6 and quad8 corner functions integrate to zero and to -A/12: with Phi = N their weighted
// gaps would vanish or change sign. The transformed bases give every node a positive weight
// sum_k D_jk = int Phi_j: tri6 2A/15 at corners and A/5 at mid-edges, quad8 A/20 and A/5
// (alpha = 1/5), in both bases.
// A rigid obstacle covers the whole facet: integrateWholeFacet's D is a fully covered
// facet's, in either basis, for every facet type (ObstacleMortarDiscretization).
TEST(MortarIntegration, AWholeFacetIsAFullyCoveredOne) {
  for (ElementType t : kFacetTypes)
    for (MultiplierBasis basis : kBases) {
      const auto& [slave, masters, covered, exact, T, n] = matchingFacets(t, basis);
      const MortarIntegrals whole = integrateWholeFacet(slave, basis);
      SCOPED_TRACE(info(t).name);
      EXPECT_TRUE(whole.masters.empty());
      EXPECT_NEAR(whole.area, exact.area, 1e-14);
      EXPECT_NEAR(whole.coveredArea, exact.area, 1e-14);
      ASSERT_EQ(whole.D.size(), covered.D.size());
      for (std::size_t i = 0; i < whole.D.size(); ++i)
        EXPECT_NEAR(whole.D[i], covered.D[i], 1e-13 * exact.area);
    }
}

TEST(MortarIntegration, QuadraticSlaveFacetsGetPositiveWeights) {
  for (ElementType t : {ElementType::Tri6, ElementType::Quad8}) {
    const Facet slave = makeFacet(t, unitSlave(t));
    const Facet master = makeMaster(t, unitSlave(t));
    const FacetMatrices exact = facetMatrices(slave);
    const int n = info(t).nodes, corners = n / 2;
    const double cornerWeight = (t == ElementType::Tri6 ? 2.0 / 15.0 : 1.0 / 20.0) * exact.area;
    EXPECT_NEAR(exact.lumped[0], t == ElementType::Tri6 ? 0.0 : -exact.area / 12, 1e-14);
    for (MultiplierBasis basis : kBases) {
      const MortarIntegrals r = integrateMortar(slave, nodeNormals(slave), {&master}, basis);
      SCOPED_TRACE(info(t).name);
      for (int j = 0; j < n; ++j) {
        double weight = 0.0;
        for (int k = 0; k < n; ++k)
          weight += r.D[j * n + k];
        EXPECT_NEAR(weight, j < corners ? cornerWeight : exact.area / 5, 1e-14);
      }
    }
  }
}

}  // namespace
}  // namespace contactlab
