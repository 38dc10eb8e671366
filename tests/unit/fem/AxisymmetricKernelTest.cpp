// The axisymmetric small-strain kernel (core/problem/AxisymmetricKernel.hpp): on every 2D cell
// type, distorted and moved to r in about [1, 4.5], the checks of a solid kernel with the
// axisymmetric twists: the only zero-energy mode is the axial translation (a radial translation
// strains the hoops), the uniform strain u_r = a r, u_z = b z gives the exact stress at every
// point, the tangent is symmetric and is the residual's derivative, and the ring's volume is
// Pappus's 2 pi r_c A.
#include "tests/unit/fem/FemTestSupport.hpp"

#include "core/problem/AxisymmetricKernel.hpp"
#include "core/problem/MassKernel.hpp"
#include "core/problem/SurfaceLoadKernel.hpp"

#include <Teuchos_LAPACK.hpp>

#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <stdexcept>

namespace contactlab {
namespace {

using test::maxAbs;
using test::nameOf;

using test::planeTypes;

// An element on test::ringNodes.
struct RingElement {
  explicit RingElement(ElementType t) : kernel(t), x(test::ringNodes(t)), n(kernel.numNodes()) {}
  AxisymmetricKernel kernel;
  std::vector<double> x;
  int n;
};

// Eigenvalues of the symmetric nd x nd matrix K, ascending.
std::vector<double> eigenvalues(std::vector<double> K, int nd) {
  std::vector<double> lambda(nd), work(4 * nd);
  int info = 0;
  Teuchos::LAPACK<int, double>().SYEV('N', 'U', nd, K.data(), nd, lambda.data(), work.data(),
                                      static_cast<int>(work.size()), &info);
  EXPECT_EQ(info, 0);
  return lambda;
}

TEST(AxisymmetricKernel, OnlyTheAxialTranslationIsAZeroEnergyMode) {
  const test::IsotropicElastic material(100.0, 0.3);
  for (ElementType t : planeTypes()) {
    RingElement e(t);
    const int nd = 2 * e.n;
    std::vector<double> u(nd, 0.0), f(nd), K(nd * nd);
    e.kernel.compute(e.x.data(), u.data(), material, nullptr, nullptr, f.data(), K.data());
    const double scale = maxAbs(K);
    for (int i = 0; i < nd; ++i)
      for (int j = 0; j < nd; ++j)
        EXPECT_NEAR(K[i * nd + j], K[j * nd + i], 1e-13 * scale) << nameOf(t);
    // The axial translation: no force at all.
    for (int a = 0; a < e.n; ++a)
      u[2 * a + 1] = 0.3;
    e.kernel.compute(e.x.data(), u.data(), material, nullptr, nullptr, f.data(), nullptr);
    EXPECT_LT(maxAbs(f), 1e-12 * scale) << nameOf(t);
    // The radial translation stretches the hoops (eps_tt = c / r): it costs energy.
    for (int a = 0; a < e.n; ++a)
      u[2 * a] = 0.1, u[2 * a + 1] = 0.0;
    e.kernel.compute(e.x.data(), u.data(), material, nullptr, nullptr, f.data(), nullptr);
    double energy = 0.0;
    for (int k = 0; k < nd; ++k)
      energy += u[k] * f[k];
    EXPECT_GT(energy, 1e-3 * scale * 0.01) << nameOf(t);
    // Exactly one zero eigenvalue, then a clear gap.
    const auto lambda = eigenvalues(K, nd);
    EXPECT_LT(std::abs(lambda[0]), 1e-10 * lambda.back()) << nameOf(t);
    EXPECT_GT(lambda[1], 1e-6 * lambda.back()) << nameOf(t) << ": a second zero-energy mode";
  }
}

TEST(AxisymmetricKernel, UniformStrainGivesTheExactStressEverywhere) {
  const test::IsotropicElastic material(100.0, 0.25);
  const double a = 0.002, b = -0.003;  // u_r = a r, u_z = b z: eps = (a, b, a, 0)
  const double eps[6] = {a, b, a, 0, 0, 0};
  double expected[6] = {};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      expected[i] += material.C()[i * 6 + j] * eps[j];
  for (ElementType t : planeTypes()) {
    RingElement e(t);
    std::vector<double> u(2 * e.n);
    for (int k = 0; k < e.n; ++k)
      u[2 * k] = a * e.x[3 * k], u[2 * k + 1] = b * e.x[3 * k + 1];
    test::expectUniformStress(e.kernel, e.x, u, material, expected, nameOf(t));
  }
}

TEST(AxisymmetricKernel, TangentIsTheResidualsDerivative) {
  const test::UnsymmetricNonlinear material;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> r(-0.05, 0.05);
  for (ElementType t : planeTypes()) {
    RingElement e(t);
    const int nd = 2 * e.n, nq = e.kernel.numQuadraturePoints();
    std::vector<double> u(nd), f(nd), K(nd * nd);
    std::vector<double> stateOld(nq), stateNew(nq);
    e.kernel.initializeState(material, stateOld.data());
    for (double& v : u)
      v = r(rng);
    e.kernel.compute(e.x.data(), u.data(), material, stateOld.data(), stateNew.data(), f.data(),
                     K.data());
    const bool unsymmetric = test::expectTangentMatchesDifferences(
        e.kernel, e.x, u, material, stateOld.data(), stateNew.data(), K, nameOf(t));
    EXPECT_TRUE(unsymmetric) << nameOf(t) << ": the test material should be unsymmetric";
  }
}

TEST(AxisymmetricKernel, MeasuresAreThoseOfTheRing) {
  // Quads on [1, 2] x [0, 3], triangles on (1, 0), (2, 0), (1, 3): Pappus's 2 pi r_c A.
  for (ElementType t : planeTypes()) {
    const auto& ref = ReferenceElement::get(t);
    std::vector<double> x(3 * ref.numNodes(), 0.0);
    for (int a = 0; a < ref.numNodes(); ++a) {
      const double* xi = &ref.nodeCoordinates()[2 * a];
      // Map the reference cell (quads [-1, 1]^2, triangles the unit one) onto the rectangle.
      const bool quad = !test::isSimplex(t);
      x[3 * a] = 1.0 + (quad ? (xi[0] + 1) / 2 : xi[0]);
      x[3 * a + 1] = 3.0 * (quad ? (xi[1] + 1) / 2 : xi[1]);
    }
    const AxisymmetricKernel kernel(t);
    // Triangle (1,0), (2,0), (1,3): area 1.5, centroid r = 4/3; quad: area 3, centroid 1.5.
    const double volume = test::isSimplex(t) ? 2 * M_PI * (4.0 / 3.0) * 1.5 : 2 * M_PI * 1.5 * 3.0;
    EXPECT_NEAR(kernel.volume(x.data()), volume, 1e-12 * volume) << nameOf(t);
    // The mass and the body force carry the same 2 pi r.
    MassKernel mass(t, true);
    std::vector<double> M(4 * ref.numNodes() * ref.numNodes(), 0.0);
    mass.add(x.data(), 2.0, false, M.data());
    double total = 0.0;
    const int nd = 2 * ref.numNodes();
    for (int i = 0; i < nd; i += 2)
      for (int j = 0; j < nd; j += 2)
        total += M[i * nd + j];
    EXPECT_NEAR(total, 2.0 * volume, 1e-12 * volume) << nameOf(t);
  }
  // A pressure on the edge r = 2, z in [0, 1]: the ring's force 2 pi 2 p, radial.
  SurfaceLoadKernel edge(ElementType::Line2, 2, -1, true);
  const double x[6] = {2.0, 0.0, 0.0, 2.0, 1.0, 0.0};
  double f[4];
  edge.pressure(x, 5.0, f);
  EXPECT_NEAR(f[0] + f[2], -2 * M_PI * 2.0 * 5.0, 1e-12);
  EXPECT_NEAR(f[1] + f[3], 0.0, 1e-12);
}

TEST(AxisymmetricKernel, RefusesThreeDimensionalCells) {
  EXPECT_THROW(AxisymmetricKernel(ElementType::Hex8), std::invalid_argument);
  EXPECT_THROW(makeElementKernel(ElementType::Hex8, Kinematics::FiniteStrain, -1, true),
               std::invalid_argument);
  // Each kinematics has its ring kernel.
  EXPECT_EQ(makeElementKernel(ElementType::Quad4, Kinematics::FiniteStrain, -1, true)->kinematics(),
            Kinematics::FiniteStrain);
  EXPECT_EQ(makeElementKernel(ElementType::Quad4, Kinematics::SmallStrain, -1, true)->kinematics(),
            Kinematics::SmallStrain);
}

}  // namespace
}  // namespace contactlab
