// The reference elements must be gmsh's exactly (node coordinates, order and basis), since
// meshes come from gmsh with their connectivity untouched.
#include "tests/unit/fem/FemTestSupport.hpp"

#include "core/fem/ReferenceElement.hpp"
#include "core/mesh/GmshSession.hpp"

#include <gmsh.h>

#include <gtest/gtest.h>

namespace contactlab {
namespace {

using test::nameOf;

class GmshConsistency : public ::testing::Test {
 protected:
  GmshSession session_;
};

TEST_F(GmshConsistency, NodeCoordinatesAndOrder) {
  for (ElementType t : test::allTypes()) {
    if (t == ElementType::Point1) continue;
    std::string name;
    int dim, order, numNodes, numPrimary;
    std::vector<double> coords;
    gmsh::model::mesh::getElementProperties(info(t).gmshType, name, dim, order, numNodes, coords,
                                            numPrimary);
    const auto& ref = ReferenceElement::get(t);
    ASSERT_EQ(dim, ref.dim()) << nameOf(t);
    ASSERT_EQ(numNodes, ref.numNodes()) << nameOf(t);
    EXPECT_EQ(order, info(t).order) << nameOf(t);
    ASSERT_EQ(coords.size(), ref.nodeCoordinates().size()) << nameOf(t);
    for (std::size_t k = 0; k < coords.size(); ++k)
      EXPECT_EQ(coords[k], ref.nodeCoordinates()[k]) << nameOf(t) << " entry " << k;
  }
}

TEST_F(GmshConsistency, BasisFunctionsAndGradients) {
  std::mt19937 rng(7);
  for (ElementType t : test::allTypes()) {
    if (t == ElementType::Point1) continue;
    const auto& ref = ReferenceElement::get(t);
    const int n = ref.numNodes(), d = ref.dim();
    std::vector<double> local;
    std::vector<std::vector<double>> points;
    for (int k = 0; k < 6; ++k) {
      points.push_back(test::randomPoint(t, rng));
      for (int i = 0; i < 3; ++i)
        local.push_back(i < d ? points.back()[i] : 0.0);
    }
    int components, orientations;
    std::vector<double> values, gradients;
    gmsh::model::mesh::getBasisFunctions(info(t).gmshType, local, "Lagrange", components, values,
                                         orientations);
    ASSERT_EQ(values.size(), points.size() * n) << nameOf(t);
    gmsh::model::mesh::getBasisFunctions(info(t).gmshType, local, "GradLagrange", components,
                                         gradients, orientations);
    ASSERT_EQ(gradients.size(), points.size() * n * 3) << nameOf(t);
    std::vector<double> N(n), dN(n * d);
    for (std::size_t p = 0; p < points.size(); ++p) {
      ref.shape(points[p].data(), N.data());
      ref.shapeDerivatives(points[p].data(), dN.data());
      for (int a = 0; a < n; ++a) {
        EXPECT_NEAR(N[a], values[p * n + a], 1e-12) << nameOf(t) << " N_" << a;
        for (int i = 0; i < d; ++i)
          EXPECT_NEAR(dN[a * d + i], gradients[(p * n + a) * 3 + i], 1e-12)
              << nameOf(t) << " dN_" << a << "/dxi_" << i;
      }
    }
  }
}

}  // namespace
}  // namespace contactlab
