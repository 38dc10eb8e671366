// Finite-strain constitutive laws: Saint Venant-Kirchhoff and neo-Hookean. Tangents against
// central finite differences, frame invariance, the linear-elastic limit, closed-form stresses,
// and the neo-Hookean J <= 0 failure. J2 small strain is J2SmallStrainTest.cpp, the registry
// entries MaterialRegistryTest.cpp.
#include "tests/unit/materials/MaterialTestSupport.hpp"

#include "core/materials/LinearElastic.hpp"
#include "core/materials/NeoHookean.hpp"
#include "core/materials/SaintVenantKirchhoff.hpp"
#include "core/materials/Tensor3.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace contactlab {
namespace {

using namespace test;
using tensor3::Mat3;

constexpr double kE = 10.0;

// The finite-strain laws under test, with their Lame constants.
struct FiniteLaw {
  std::string label;
  std::shared_ptr<Material> material;
  double lambda, mu;
};

std::vector<FiniteLaw> finiteLaws() {
  std::vector<FiniteLaw> laws;
  for (double nu : {0.3, 0.45}) {
    const double lambda = kE * nu / ((1 + nu) * (1 - 2 * nu)), mu = kE / (2 * (1 + nu));
    const std::string tag = " nu=" + std::to_string(nu);
    laws.push_back({"saint-venant-kirchhoff" + tag, std::make_shared<SaintVenantKirchhoff>(kE, nu),
                    lambda, mu});
    laws.push_back({"neo-hookean" + tag,
                    std::make_shared<NeoHookean>(NeoHookean::fromYoungPoisson(kE, nu)), lambda,
                    mu});
  }
  // From C10 and D1: mu = 2 C10 = 3, K = 2 / D1 = 20.
  laws.push_back(
      {"neo-hookean C10/D1", std::make_shared<NeoHookean>(1.5, 0.1), 20.0 - 2.0 / 3.0 * 3.0, 3.0});
  return laws;
}

// ---------------------------------------------------------------------------------------------
// Finite strain: tangents, invariance, linear limit.

TEST(FiniteStrainLaws, TangentMatchesCentralDifferences) {
  for (const auto& law : finiteLaws()) {
    std::mt19937 gen(20240611);
    for (int sample = 0; sample < 30; ++sample) {
      const bool planeStrain = sample >= 20;  // 20 general samples, 10 plane-strain shaped
      const Mat3 F = randomF(gen, planeStrain);
      ASSERT_GT(tensor3::determinant(F), 0.0);
      EXPECT_LT(dPdFError(*law.material, F), 1e-6) << law.label << " sample " << sample;
    }
  }
}

TEST(FiniteStrainLaws, FrameInvariance) {
  for (const auto& law : finiteLaws()) {
    std::mt19937 gen(7);
    for (int sample = 0; sample < 10; ++sample) {
      const Mat3 F = randomF(gen, sample % 2 == 1);
      const Mat3 Q = rotation({0.3, -1.0, 0.5 + sample}, 0.4 + 0.5 * sample);
      const Mat3 P = evaluateF(*law.material, F).P;
      const Mat3 PofQF = evaluateF(*law.material, tensor3::multiply(Q, F)).P;
      const Mat3 QP = tensor3::multiply(Q, P);
      double err = 0.0;
      for (int a = 0; a < 9; ++a)
        err = std::max(err, std::abs(PofQF[a] - QP[a]));
      EXPECT_LT(err, 1e-12 * kE) << law.label << " sample " << sample;
    }
  }
}

TEST(FiniteStrainLaws, IdentityGivesZeroStressAndTheLinearElasticTangent) {
  for (const auto& law : finiteLaws()) {
    const MaterialOutput out = evaluateF(*law.material, tensor3::identity());
    EXPECT_LT(maxAbs(out.P.data(), 9), 1e-14 * kE) << law.label;
    // Reference: LinearElastic's Voigt matrix as a 4th order tensor. With engineering shears,
    // C_ijkl = D[voigt(i, j)][voigt(k, l)] (minor symmetry).
    const double E = law.mu * (3 * law.lambda + 2 * law.mu) / (law.lambda + law.mu);
    const double nu = law.lambda / (2 * (law.lambda + law.mu));
    LinearElastic linear(E, nu);
    MaterialInput in;
    MaterialOutput lin;
    linear.evaluate(in, lin);
    const int voigt[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J)
        for (int k = 0; k < 3; ++k)
          for (int L = 0; L < 3; ++L)
            EXPECT_NEAR(out.dPdF[(i * 3 + J) * 9 + k * 3 + L],
                        lin.tangent[voigt[i][J] * 6 + voigt[k][L]], 1e-12 * kE)
                << law.label << " " << i << J << k << L;
  }
}

// ---------------------------------------------------------------------------------------------
// Saint Venant-Kirchhoff closed form.

TEST(SaintVenantKirchhoff, UniaxialStressClosedForm) {
  // S_22 = 0 gives E_22 = -nu E_11, hence the lateral stretch, and S_11 = E E_11:
  // P_11 = E s (s^2 - 1) / 2.
  const double nu = 0.3;
  const SaintVenantKirchhoff svk(kE, nu);
  for (double s : {0.7, 0.9, 1.05, 1.3, 1.6}) {
    const double lateral = std::sqrt(1.0 - nu * (s * s - 1.0));
    const Mat3 P = evaluateF(svk, diagonal(s, lateral, lateral)).P;
    EXPECT_NEAR(P[0], kE * s * (s * s - 1.0) / 2.0, 1e-12 * kE) << s;
    for (int a = 1; a < 9; ++a)
      EXPECT_NEAR(P[a], 0.0, 1e-12 * kE) << s << " component " << a;
  }
}

TEST(SaintVenantKirchhoff, SimpleShearClosedForm) {
  // F = I + g e_x (x) e_y: E = [[0, g/2, 0], [g/2, g^2/2, 0], [0, 0, 0]], tr E = g^2 / 2.
  const SaintVenantKirchhoff svk(kE, 0.25);
  const double lambda = svk.lambda(), mu = svk.mu();
  for (double g : {0.1, 0.5, 1.0}) {
    const Mat3 F = {1, g, 0, 0, 1, 0, 0, 0, 1};
    const double tr = g * g / 2;
    const Mat3 S = {lambda * tr, mu * g, 0, mu * g, lambda * tr + mu * g * g, 0, 0, 0, lambda * tr};
    const Mat3 expected = tensor3::multiply(F, S);
    const Mat3 P = evaluateF(svk, F).P;
    for (int a = 0; a < 9; ++a)
      EXPECT_NEAR(P[a], expected[a], 1e-12 * kE) << g << " component " << a;
    // Independent of the product above: P_12 = S_12 + g S_22, P_21 = S_21.
    EXPECT_NEAR(P[1], mu * g + g * (lambda * tr + mu * g * g), 1e-12 * kE);
    EXPECT_NEAR(P[3], mu * g, 1e-12 * kE);
  }
}

// ---------------------------------------------------------------------------------------------
// Neo-Hookean closed forms and failure.

TEST(NeoHookean, SimpleShearGivesMuTimesDeviatoricLeftCauchyGreen) {
  // J = 1: sigma = mu dev(b), b = F F^T; sigma_12 = mu g, sigma_11 - sigma_22 = mu g^2.
  const NeoHookean nh = NeoHookean::fromYoungPoisson(kE, 0.3);
  const double mu = nh.shearModulus();
  for (double g : {0.1, 0.5, 2.0}) {
    const Mat3 F = {1, g, 0, 0, 1, 0, 0, 0, 1};
    const Mat3 sigma = cauchy(evaluateF(nh, F).P, F);
    const Mat3 expected = {2 * mu * g * g / 3, mu * g, 0, mu * g, -mu * g * g / 3, 0, 0, 0,
                           -mu * g * g / 3};
    for (int a = 0; a < 9; ++a)
      EXPECT_NEAR(sigma[a], expected[a], 1e-12 * kE * (1 + g * g)) << g << " component " << a;
  }
}

TEST(NeoHookean, HydrostaticStretchGivesBulkPressure) {
  // F = s I: isochoric part is I, sigma = K (J - 1) I with K = E / (3 (1 - 2 nu)).
  const double nu = 0.3, K = kE / (3 * (1 - 2 * nu));
  const NeoHookean nh = NeoHookean::fromYoungPoisson(kE, nu);
  for (double s : {0.6, 0.95, 1.1, 1.5}) {
    const Mat3 F = diagonal(s, s, s);
    const Mat3 sigma = cauchy(evaluateF(nh, F).P, F);
    const double J = s * s * s;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        EXPECT_NEAR(sigma[i * 3 + j], i == j ? K * (J - 1) : 0.0, 1e-12 * kE) << s;
  }
}

TEST(NeoHookean, UniaxialStressWithLateralStretchSolvedByTheLaw) {
  const double nu = 0.3;
  const NeoHookean nh = NeoHookean::fromYoungPoisson(kE, nu);
  const double mu = nh.shearModulus(), K = nh.bulkModulus();
  // Lateral stretch l from P_22(diag(s, l, l)) = 0 by Newton with the law's own tangent.
  auto uniaxial = [&](double s) {
    double l = 1.0;
    for (int it = 0; it < 50; ++it) {
      const MaterialOutput out = evaluateF(nh, diagonal(s, l, l));
      const double r = out.P[4];
      if (std::abs(r) < 1e-14 * kE) break;
      const double drdl = out.dPdF[4 * 9 + 4] + out.dPdF[4 * 9 + 8];
      l -= r / drdl;
    }
    return l;
  };
  for (double s : {0.7, 0.9, 1.2, 1.8}) {
    const double l = uniaxial(s);
    const MaterialOutput out = evaluateF(nh, diagonal(s, l, l));
    EXPECT_NEAR(out.P[4], 0.0, 1e-12 * kE);
    EXPECT_NEAR(out.P[8], 0.0, 1e-12 * kE);
    // W(s, l) = C10 (J^-2/3 (s^2 + 2 l^2) - 3) + (J - 1)^2 / D1, J = s l^2: P_11 = dW/ds.
    const double J = s * l * l, I1 = s * s + 2 * l * l;
    const double P11 = mu * std::pow(J, -2.0 / 3.0) * (s - I1 / (3 * s)) + K * (J - 1) * J / s;
    EXPECT_NEAR(out.P[0], P11, 1e-12 * kE) << s;
    EXPECT_GT((out.P[0]) * (s - 1), 0.0) << s;  // tension in extension, compression in shortening
  }
  // Small stretch: Young's modulus and Poisson's ratio.
  const double e = 1e-6, l = uniaxial(1 + e);
  EXPECT_NEAR(evaluateF(nh, diagonal(1 + e, l, l)).P[0] / e, kE, 1e-4 * kE);
  EXPECT_NEAR(-(l - 1) / e, nu, 1e-4);
}

TEST(NeoHookean, NonPositiveJSetsFailedWithoutThrowing) {
  const NeoHookean nh = NeoHookean::fromYoungPoisson(kE, 0.3);
  const std::vector<std::pair<Mat3, std::string>> cases = {
      {diagonal(1, 1, -0.1), "neo-hookean: J = -0.1 <= 0"},
      {diagonal(1, 0, 1), "neo-hookean: J = 0 <= 0"},
      {{0, 1, 0, 1, 0, 0, 0, 0, 1}, "neo-hookean: J = -1 <= 0"}};  // a reflection
  for (const auto& [F, message] : cases) {
    MaterialInput in;
    in.F = F;
    MaterialOutput out;
    EXPECT_NO_THROW(nh.evaluate(in, out));
    EXPECT_TRUE(out.failed) << message;
    EXPECT_EQ(out.failure, message);
    for (double p : out.P)
      EXPECT_TRUE(std::isfinite(p)) << message;
    for (double d : out.dPdF)
      EXPECT_TRUE(std::isfinite(d)) << message;
  }
  // A NaN F fails the same way instead of producing NaN stresses.
  MaterialInput in;
  in.F = tensor3::identity();
  in.F[4] = std::nan("");
  MaterialOutput out;
  nh.evaluate(in, out);
  EXPECT_TRUE(out.failed);
  EXPECT_EQ(out.failure.rfind("neo-hookean: J = ", 0), 0u) << out.failure;
}

TEST(NeoHookean, YoungPoissonAndCoefficientsGiveTheSameLaw) {
  const double E = 210.0, nu = 0.3;
  const double mu = E / (2 * (1 + nu)), K = E / (3 * (1 - 2 * nu));
  const NeoHookean a = NeoHookean::fromYoungPoisson(E, nu);
  EXPECT_NEAR(a.C10(), mu / 2, 1e-12 * E);
  EXPECT_NEAR(a.D1(), 2 / K, 1e-12 / E);
  const NeoHookean b(mu / 2, 2 / K);
  std::mt19937 gen(3);
  const Mat3 F = randomF(gen, false);
  const Mat3 Pa = evaluateF(a, F).P, Pb = evaluateF(b, F).P;
  for (int i = 0; i < 9; ++i)
    EXPECT_NEAR(Pa[i], Pb[i], 1e-12 * E);
}

}  // namespace
}  // namespace contactlab
