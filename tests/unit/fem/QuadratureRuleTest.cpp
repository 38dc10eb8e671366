#include "tests/unit/fem/FemTestSupport.hpp"

#include "core/fem/QuadratureRule.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>

namespace contactlab {
namespace {

using test::isSimplex;
using test::nameOf;

double factorial(int n) {
  return n <= 1 ? 1.0 : n * factorial(n - 1);
}

// Exact integral of xi^e[0] * eta^e[1] * zeta^e[2] over the reference cell.
double exactMonomial(ElementType t, const int* e, int d) {
  if (isSimplex(t)) {
    double num = 1;
    int total = d;
    for (int i = 0; i < d; ++i)
      num *= factorial(e[i]), total += e[i];
    return num / factorial(total);
  }
  double v = 1;
  for (int i = 0; i < d; ++i)
    v *= e[i] % 2 ? 0.0 : 2.0 / (e[i] + 1);
  return v;
}

double integrate(const QuadratureRule& r, const int* e) {
  double s = 0;
  for (int q = 0; q < r.size(); ++q) {
    double v = r.weights[q];
    for (int i = 0; i < r.dim; ++i)
      v *= std::pow(r.points[q * r.dim + i], e[i]);
    s += v;
  }
  return s;
}

// Every monomial the rule must integrate: total degree <= p on simplices, each exponent <= p
// on tensor cells.
void checkExactness(ElementType t, int p) {
  const int d = info(t).dim;
  const auto& r = quadratureRule(t, p);
  ASSERT_EQ(r.dim, d);
  ASSERT_EQ(r.points.size(), std::size_t(r.size() * d));
  int e[3] = {0, 0, 0};
  const int top[3] = {p, d > 1 ? p : 0, d > 2 ? p : 0};
  for (e[2] = 0; e[2] <= top[2]; ++e[2])
    for (e[1] = 0; e[1] <= top[1]; ++e[1])
      for (e[0] = 0; e[0] <= top[0]; ++e[0]) {
        if (isSimplex(t) && e[0] + e[1] + e[2] > p) continue;
        const double exact = exactMonomial(t, e, d);
        EXPECT_NEAR(integrate(r, e), exact, 1e-13 * (1 + std::abs(exact)))
            << nameOf(t) << " degree " << p << " exponents " << e[0] << " " << e[1] << " " << e[2];
      }
}

TEST(QuadratureRule, ExactOnMonomials) {
  for (ElementType t : test::allTypes()) {
    if (t == ElementType::Point1) continue;
    const int maxDegree = isSimplex(t) ? 12 : (info(t).dim == 3 ? 11 : 13);
    for (int p = 0; p <= maxDegree; ++p)
      checkExactness(t, p);
  }
}

TEST(QuadratureRule, PositiveWeightsInsideTheCellSummingToItsMeasure) {
  for (ElementType t : test::allTypes()) {
    const int d = info(t).dim;
    const double measure = isSimplex(t) ? 1.0 / factorial(d) : std::pow(2.0, d);
    for (int p = 0; p <= 10; ++p) {
      const auto& r = quadratureRule(t, p);
      double sum = 0;
      for (int q = 0; q < r.size(); ++q) {
        EXPECT_GT(r.weights[q], 0.0) << nameOf(t) << " degree " << p;
        sum += r.weights[q];
        double bary = 1;
        for (int i = 0; i < d; ++i) {
          const double x = r.points[q * d + i];
          if (isSimplex(t)) {
            EXPECT_GT(x, 0.0);
            bary -= x;
          } else {
            EXPECT_LT(std::abs(x), 1.0);
          }
        }
        if (isSimplex(t)) {
          EXPECT_GT(bary, 0.0) << nameOf(t) << " degree " << p;
        }
      }
      EXPECT_NEAR(sum, measure, 1e-13) << nameOf(t) << " degree " << p;
    }
  }
}

TEST(QuadratureRule, PointCountsAndCaching) {
  EXPECT_EQ(quadratureRule(ElementType::Hex27, 4).size(), 27);
  EXPECT_EQ(quadratureRule(ElementType::Hex8, 2).size(), 8);
  EXPECT_EQ(quadratureRule(ElementType::Quad4, 3).size(), 4);
  EXPECT_EQ(quadratureRule(ElementType::Line3, 11).size(), 6);
  EXPECT_EQ(quadratureRule(ElementType::Tri3, 1).size(), 1);
  EXPECT_EQ(quadratureRule(ElementType::Tri6, 2).size(), 3);
  EXPECT_EQ(quadratureRule(ElementType::Tri6, 5).size(), 7);
  EXPECT_EQ(quadratureRule(ElementType::Tet4, 0).size(), 1);
  EXPECT_EQ(quadratureRule(ElementType::Tet10, 2).size(), 4);
  EXPECT_EQ(quadratureRule(ElementType::Point1, 3).size(), 1);
  EXPECT_EQ(&quadratureRule(ElementType::Hex20, 4), &quadratureRule(ElementType::Hex20, 4));
  EXPECT_THROW(quadratureRule(ElementType::Quad4, -1), std::invalid_argument);
}

TEST(QuadratureRule, StiffnessDegrees) {
  EXPECT_EQ(stiffnessQuadratureDegree(ElementType::Quad4), 2);
  EXPECT_EQ(stiffnessQuadratureDegree(ElementType::Hex8), 2);
  EXPECT_EQ(stiffnessQuadratureDegree(ElementType::Quad8), 4);
  EXPECT_EQ(stiffnessQuadratureDegree(ElementType::Quad9), 4);
  EXPECT_EQ(stiffnessQuadratureDegree(ElementType::Hex20), 4);
  EXPECT_EQ(stiffnessQuadratureDegree(ElementType::Hex27), 4);
  EXPECT_EQ(stiffnessQuadratureDegree(ElementType::Tri3), 0);
  EXPECT_EQ(stiffnessQuadratureDegree(ElementType::Tet4), 0);
  EXPECT_EQ(stiffnessQuadratureDegree(ElementType::Tri6), 2);
  EXPECT_EQ(stiffnessQuadratureDegree(ElementType::Tet10), 3);
}

}  // namespace
}  // namespace contactlab
