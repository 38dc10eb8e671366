// The element technologies' kernels (B-bar / mixed small strain, F-bar, mixed finite strain):
// tangents against central differences in elastic and plastic states, rigid motions, the
// patch test, the reduction of the finite-strain kernels to the small-strain ones at u = 0, the
// symmetry each one promises, and the count of volumetric constraints that makes them free of
// locking (one per pressure mode, against one per quadrature point under full integration).
#include "tests/unit/fem/FemTestSupport.hpp"

#include "core/materials/J2SmallStrain.hpp"
#include "core/materials/SimoMiehe.hpp"
#include "core/problem/FBarKernel.hpp"
#include "core/problem/ProjectedDilatationKernel.hpp"
#include "core/problem/ProjectedJacobianKernel.hpp"

#include <functional>
#include <gtest/gtest.h>
#include <memory>
#include <random>

namespace contactlab {
namespace {

using test::maxAbs;
using test::nameOf;

// One kernel under test, with the geometry it is built for.
struct Case {
  std::string label;
  std::function<std::unique_ptr<ElementKernel>()> make;
  ElementType type;
  bool axisymmetric;
};

bool isLinearQuadOrHex(ElementType t) {
  return t == ElementType::Quad4 || t == ElementType::Hex8;
}

int degreeFor(ElementType t) {
  return isLinearQuadOrHex(t) ? 0 : 1;
}

// Every geometry (plane strain and the ring for 2D cells, 3D) of every cell type but the linear
// simplices, for the small-strain (finite = false) or finite-strain technologies.
std::vector<Case> cases(bool finite) {
  std::vector<Case> list;
  for (ElementType t : test::solidTypes()) {
    if (t == ElementType::Tri3 || t == ElementType::Tet4) continue;
    for (bool ring : {false, true}) {
      if (ring && info(t).dim != 2) continue;
      const std::string where = nameOf(t) + (ring ? " ring" : "");
      const int degree = degreeFor(t);
      if (!finite) {
        list.push_back(
            {"projected dilatation P" + std::to_string(degree) + " " + where,
             [=] { return std::make_unique<ProjectedDilatationKernel>(t, degree, ring); }, t,
             ring});
        continue;
      }
      list.push_back({"projected jacobian P" + std::to_string(degree) + " " + where,
                      [=] { return std::make_unique<ProjectedJacobianKernel>(t, degree, ring); }, t,
                      ring});
      if (isLinearQuadOrHex(t))
        list.push_back(
            {"f-bar " + where, [=] { return std::make_unique<FBarKernel>(t, ring); }, t, ring});
    }
  }
  return list;
}

std::vector<double> nodesOf(const Case& c) {
  return c.axisymmetric ? test::ringNodes(c.type) : test::distortedNodes(c.type);
}

std::vector<double> randomDisplacement(int nd, double size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> r(-size, size);
  std::vector<double> u(nd);
  for (double& v : u)
    v = r(rng);
  return u;
}

// The affine field u = G x + c (2D: G's upper-left block); in the ring u_r = G_00 r.
std::vector<double> affine(const Case& c, const std::vector<double>& x, const double (&G)[3][3],
                           const double* shift) {
  const int d = info(c.type).dim, n = info(c.type).nodes;
  std::vector<double> u(n * d);
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < d; ++i) {
      u[a * d + i] = (c.axisymmetric && i == 0) ? 0.0 : shift[i];
      for (int j = 0; j < d; ++j)
        u[a * d + i] += G[i][j] * x[3 * a + j];
    }
  return u;
}

J2SmallStrain j2(double poissonRatio, double hardening) {
  J2SmallStrain::Parameters p;
  p.youngModulus = TemperatureDependent(200.0);
  p.poissonRatio = TemperatureDependent(poissonRatio);
  p.yieldStress = TemperatureDependent(0.2);
  p.isotropicHardening = TemperatureDependent(hardening);
  return J2SmallStrain(p);
}

SimoMiehe hardeningSimoMiehe() {
  SimoMiehe::Parameters p;
  p.youngModulus = 200.0;
  p.poissonRatio = 0.3;
  p.yieldStress = 2.0;
  p.isotropicHardening = 20.0;
  return SimoMiehe(p);
}

template <class Law>
void checkTangent(const Case& c, const Law& law, const std::vector<double>& u,
                  const std::string& what) {
  const auto kernel = c.make();
  const auto x = nodesOf(c);
  const int nd = kernel->numDofs();
  std::vector<double> stateOld(kernel->numQuadraturePoints() * law.stateSize()),
      stateNew(stateOld.size());
  if (!stateOld.empty()) kernel->initializeState(law, stateOld.data());
  std::vector<double> f(nd), K(nd * nd);
  kernel->compute(x.data(), u.data(), law, stateOld.data(), stateNew.data(), f.data(), K.data());
  test::expectTangentMatchesDifferences(*kernel, x, u, law, stateOld.data(), stateNew.data(), K,
                                        c.label + " " + what);
}

TEST(TechnologyKernels, SmallStrainTangentsMatchDifferences) {
  const test::IsotropicElastic nearlyIncompressible(100.0, 0.4999);
  const test::UnsymmetricNonlinear unsymmetric;
  const J2SmallStrain plastic = j2(0.3, 20.0), perfect = j2(0.48, 0.0);
  for (const Case& c : cases(false)) {
    const int nd = info(c.type).nodes * info(c.type).dim;
    checkTangent(c, nearlyIncompressible, randomDisplacement(nd, 0.01, 1), "elastic");
    checkTangent(c, unsymmetric, randomDisplacement(nd, 0.01, 2), "unsymmetric law");
    // Strains around 1 %, five times the yield strain: every point plastic.
    checkTangent(c, plastic, randomDisplacement(nd, 0.02, 3), "plastic");
    checkTangent(c, perfect, randomDisplacement(nd, 0.02, 4), "perfectly plastic");
  }
}

TEST(TechnologyKernels, FiniteStrainTangentsMatchDifferences) {
  const test::TestKirchhoff kirchhoff(60.0, 40.0);
  const SimoMiehe plastic = hardeningSimoMiehe();
  for (const Case& c : cases(true)) {
    const int nd = info(c.type).nodes * info(c.type).dim;
    checkTangent(c, kirchhoff, randomDisplacement(nd, 0.06, 4), "large strain");
    checkTangent(c, plastic, randomDisplacement(nd, 0.05, 5), "plastic");
  }
}

TEST(TechnologyKernels, RigidMotionsGiveZeroResidual) {
  const test::IsotropicElastic elastic(100.0, 0.49);
  const test::TestKirchhoff kirchhoff(60.0, 40.0);
  for (bool finite : {false, true})
    for (const Case& c : cases(finite)) {
      const auto kernel = c.make();
      const auto x = nodesOf(c);
      const int d = info(c.type).dim;
      // Small strain: a translation and an infinitesimal rotation; finite: a rotation of 40
      // degrees. The ring moves along its axis only.
      double G[3][3] = {};
      if (!c.axisymmetric) {
        const double s = finite ? std::sin(0.7) : 1e-3, co = finite ? std::cos(0.7) - 1 : 0.0;
        G[0][0] = co, G[0][1] = -s, G[1][0] = s, G[1][1] = co;
        if (d == 3) G[2][2] = 0.0;
      }
      const double shift[3] = {0.2, -0.3, 0.1};
      const auto u = affine(c, x, G, shift);
      std::vector<double> f(kernel->numDofs());
      if (finite)
        kernel->compute(x.data(), u.data(), kirchhoff, nullptr, nullptr, f.data(), nullptr);
      else
        kernel->compute(x.data(), u.data(), elastic, nullptr, nullptr, f.data(), nullptr);
      EXPECT_LT(maxAbs(f), 1e-10) << c.label;
    }
}

TEST(TechnologyKernels, PassThePatchTest) {
  // A uniform strain is reproduced exactly: the projected dilatation of a constant trace is
  // that trace, and F-bar's centre has the points' J.
  const test::IsotropicElastic elastic(100.0, 0.45);
  const test::TestKirchhoff kirchhoff(60.0, 40.0);
  for (bool finite : {false, true})
    for (const Case& c : cases(finite)) {
      const auto kernel = c.make();
      const auto x = nodesOf(c);
      const double G[3][3] = {{0.02, c.axisymmetric ? 0.0 : 0.01, 0.005},
                              {0.015, -0.01, 0.002},
                              {0.004, -0.003, 0.012}};
      const double shift[3] = {0.1, 0.2, -0.1};
      const auto u = affine(c, x, G, shift);
      std::vector<double> stress(6 * kernel->numQuadraturePoints());
      if (finite)
        kernel->stresses(x.data(), u.data(), kirchhoff, nullptr, nullptr, stress.data(), nullptr);
      else
        kernel->stresses(x.data(), u.data(), elastic, nullptr, nullptr, stress.data(), nullptr);
      for (int q = 1; q < kernel->numQuadraturePoints(); ++q)
        for (int k = 0; k < 6; ++k)
          EXPECT_NEAR(stress[6 * q + k], stress[k], 1e-10) << c.label << " q=" << q;
    }
}

TEST(TechnologyKernels, FiniteStrainReducesToSmallStrainAtRest) {
  // dP/dF of Saint Venant-Kirchhoff at F = I is the isotropic C of the same lambda and mu.
  const double E = 100.0, nu = 0.45, lambda = E * nu / ((1 + nu) * (1 - 2 * nu)),
               mu = E / (2 * (1 + nu));
  const test::IsotropicElastic elastic(E, nu);
  const test::TestKirchhoff kirchhoff(lambda, mu);
  for (const Case& c : cases(true)) {
    const bool fbar = c.label.rfind("f-bar", 0) == 0;
    const auto kernel = c.make();
    // F-bar's centre divergence is the points' mean on affine cells only: compare it there.
    const auto x =
        fbar ? (c.axisymmetric ? test::ringNodes(c.type) : test::distortedNodes(c.type, 0.0))
             : nodesOf(c);
    if (fbar && c.axisymmetric) continue;  // r varies across the ring: no affine reduction
    ProjectedDilatationKernel small(c.type, fbar ? 0 : degreeFor(c.type), c.axisymmetric);
    const int nd = kernel->numDofs();
    std::vector<double> u(nd, 0.0), f(nd), Kf(nd * nd), Ks(nd * nd);
    kernel->compute(x.data(), u.data(), kirchhoff, nullptr, nullptr, f.data(), Kf.data());
    small.compute(x.data(), u.data(), elastic, nullptr, nullptr, f.data(), Ks.data());
    const double scale = maxAbs(Ks);
    for (int k = 0; k < nd * nd; ++k)
      ASSERT_NEAR(Kf[k], Ks[k], 1e-10 * scale) << c.label << " entry " << k;
  }
}

TEST(TechnologyKernels, SymmetryIsAsPromised) {
  const test::TestKirchhoff kirchhoff(60.0, 40.0);
  for (const Case& c : cases(true)) {
    const auto kernel = c.make();
    const auto x = nodesOf(c);
    const int nd = kernel->numDofs();
    const auto u = randomDisplacement(nd, 0.06, 6);
    std::vector<double> f(nd), K(nd * nd);
    kernel->compute(x.data(), u.data(), kirchhoff, nullptr, nullptr, f.data(), K.data());
    double asymmetry = 0.0;
    for (int i = 0; i < nd; ++i)
      for (int k = 0; k < nd; ++k)
        asymmetry = std::max(asymmetry, std::abs(K[i * nd + k] - K[k * nd + i]));
    if (c.label.rfind("f-bar", 0) == 0)
      EXPECT_GT(asymmetry, 1e-6 * maxAbs(K)) << c.label;  // not the gradient of an energy
    else
      EXPECT_LT(asymmetry, 1e-12 * maxAbs(K)) << c.label;
  }
}

// The numerical rank of a square matrix (Gaussian elimination with full pivoting).
int rankOf(std::vector<double> A, int n) {
  const double scale = maxAbs(A);
  int rank = 0;
  std::vector<bool> rowUsed(n, false), colUsed(n, false);
  for (int step = 0; step < n; ++step) {
    int pr = -1, pc = -1;
    double best = 1e-9 * scale;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if (!rowUsed[i] && !colUsed[j] && std::abs(A[i * n + j]) > best)
          best = std::abs(A[i * n + j]), pr = i, pc = j;
    if (pr < 0) break;
    ++rank;
    rowUsed[pr] = colUsed[pc] = true;
    for (int i = 0; i < n; ++i) {
      if (rowUsed[i]) continue;
      const double f = A[i * n + pc] / A[pr * n + pc];
      for (int j = 0; j < n; ++j)
        A[i * n + j] -= f * A[pr * n + j];
    }
  }
  return rank;
}

TEST(TechnologyKernels, ConstrainTheVolumeOncePerPressureMode) {
  // With mu = 0 the element matrix is the volumetric constraint lambda int b_bar b_bar^T: its
  // rank is the number of constraints an incompressible material puts on the element. Full
  // integration constrains the volume at every quadrature point (quad4: 4, hex8: 8), which is
  // what locks; the technologies once per pressure mode (P0: 1, P1: dim + 1).
  const test::IsotropicElastic volumetric(1.0, 0.5 - 1e-12);
  for (const Case& c : cases(false)) {
    const auto kernel = c.make();
    const auto x = nodesOf(c);
    const int nd = kernel->numDofs();
    std::vector<double> u(nd, 0.0), f(nd), K(nd * nd), Kfull(nd * nd);
    kernel->compute(x.data(), u.data(), volumetric, nullptr, nullptr, f.data(), K.data());
    const auto full = makeElementKernel(c.type, Kinematics::SmallStrain, -1, c.axisymmetric);
    full->compute(x.data(), u.data(), volumetric, nullptr, nullptr, f.data(), Kfull.data());
    const int modes = degreeFor(c.type) == 0 ? 1 : info(c.type).dim + 1;
    // The shear part (mu ~ 3e-7 lambda) stays below the rank threshold.
    EXPECT_EQ(rankOf(K, nd), modes) << c.label;
    // The plane tri6's three-point rule constrains it as often as P1 does.
    if (c.type == ElementType::Tri6 && !c.axisymmetric)
      EXPECT_EQ(rankOf(Kfull, nd), modes) << c.label << " (full integration)";
    else
      EXPECT_GT(rankOf(Kfull, nd), modes) << c.label << " (full integration)";
  }
}

}  // namespace
}  // namespace contactlab
