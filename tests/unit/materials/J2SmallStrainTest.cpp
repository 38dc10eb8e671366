// j2-small-strain: the radial return with isotropic and kinematic hardening. The state layout;
// the consistent tangent against central differences (elastic, plastic, perfectly plastic,
// unloading) and its symmetry; consistency on the yield surface; the bilinear uniaxial closed
// form with elastic unloading; the Bauschinger reverse yield; pure pressure never yields.
#include "tests/unit/materials/MaterialTestSupport.hpp"

#include "core/materials/J2SmallStrain.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <vector>

namespace contactlab {
namespace {

using namespace test;
using Voigt = std::array<double, 6>;
using J2State = std::array<double, J2SmallStrain::kStateSize>;

struct J2Result {
  Voigt stress;
  std::array<double, 36> tangent;
  J2State state;
};

J2Result evaluateJ2(const J2SmallStrain& m, const Voigt& strain, const J2State& stateOld) {
  MaterialInput in;
  in.strain = strain;
  in.stateOld = stateOld.data();
  J2Result r;
  r.state.fill(std::nan(""));  // the law must write every entry
  MaterialOutput out;
  out.stateNew = r.state.data();
  m.evaluate(in, out);
  EXPECT_FALSE(out.failed);
  r.stress = out.stress;
  r.tangent = out.tangent;
  for (double s : r.state)
    EXPECT_TRUE(std::isfinite(s));
  return r;
}

J2SmallStrain::Parameters steel(double Hiso, double Hkin) {
  J2SmallStrain::Parameters p;
  p.youngModulus = 200e3;
  p.poissonRatio = 0.3;
  p.yieldStress = 250.0;
  p.isotropicHardening = Hiso;
  p.kinematicHardening = Hkin;
  return p;
}

J2State zeroState(const J2SmallStrain& m) {
  J2State s;
  s.fill(7.0);
  m.initializeState(s.data());
  return s;
}

// max |tangent - central differences of the stress| / max |tangent|, from the same stateOld.
double tangentError(const J2SmallStrain& m, const Voigt& strain, const J2State& stateOld) {
  const J2Result r = evaluateJ2(m, strain, stateOld);
  return centralDifferenceError<6, 6>(
      [&](const Voigt& e) { return evaluateJ2(m, e, stateOld).stress; }, strain, r.tangent.data(),
      1e-8);
}

// Von Mises relative stress sqrt(3/2) |dev(sigma) - alpha| and the current yield stress.
double relativeMises(const Voigt& stress, const J2State& state) {
  const double p = (stress[0] + stress[1] + stress[2]) / 3;
  double s2 = 0;
  for (int a = 0; a < 6; ++a) {
    const double xi = stress[a] - (a < 3 ? p : 0.0) - state[J2SmallStrain::kBackStress + a];
    s2 += (a < 3 ? 1.0 : 2.0) * xi * xi;
  }
  return std::sqrt(1.5 * s2);
}

Voigt randomStrain(std::mt19937& gen, double size, bool planeStrain) {
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  Voigt e;
  for (int a = 0; a < 6; ++a)
    e[a] = planeStrain && (a == 2 || a == 4 || a == 5) ? 0.0 : entry(gen);
  const double n = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2] +
                             0.5 * (e[3] * e[3] + e[4] * e[4] + e[5] * e[5]));
  for (double& x : e)
    x *= size / n;
  return e;
}

Voigt add(const Voigt& a, const Voigt& b, double t = 1.0) {
  Voigt c;
  for (int i = 0; i < 6; ++i)
    c[i] = a[i] + t * b[i];
  return c;
}

// One uniaxial stress step: eps_11 is prescribed, the other five strains are found (Newton on
// the law's tangent) so that the other five stresses vanish. `strain` holds the initial guess
// and returns the solution.
J2Result uniaxialStep(const J2SmallStrain& m, double eps11, const J2State& stateOld,
                      Voigt& strain) {
  strain[0] = eps11;
  J2Result r{};
  for (int it = 0; it < 50; ++it) {
    r = evaluateJ2(m, strain, stateOld);
    double residual = 0;
    for (int a = 1; a < 6; ++a)
      residual = std::max(residual, std::abs(r.stress[a]));
    if (residual < 1e-10 * m.parameters().yieldStress.at(20.0)) return r;
    // Solve K x = -sigma on the 5x5 block (rows/columns 1..5), Gauss with partial pivoting.
    double A[5][6];
    for (int a = 0; a < 5; ++a) {
      for (int b = 0; b < 5; ++b)
        A[a][b] = r.tangent[(a + 1) * 6 + (b + 1)];
      A[a][5] = -r.stress[a + 1];
    }
    for (int c = 0; c < 5; ++c) {
      int pivot = c;
      for (int a = c + 1; a < 5; ++a)
        if (std::abs(A[a][c]) > std::abs(A[pivot][c])) pivot = a;
      for (int b = 0; b < 6; ++b)
        std::swap(A[c][b], A[pivot][b]);
      for (int a = c + 1; a < 5; ++a) {
        const double factor = A[a][c] / A[c][c];
        for (int b = c; b < 6; ++b)
          A[a][b] -= factor * A[c][b];
      }
    }
    double x[5];
    for (int a = 4; a >= 0; --a) {
      x[a] = A[a][5];
      for (int b = a + 1; b < 5; ++b)
        x[a] -= A[a][b] * x[b];
      x[a] /= A[a][a];
    }
    for (int a = 0; a < 5; ++a)
      strain[a + 1] += x[a];
  }
  ADD_FAILURE() << "uniaxial stress iteration did not converge at eps_11 = " << eps11;
  return r;
}

TEST(J2SmallStrain, InitializeStateZeroesAndStateLayout) {
  const J2SmallStrain m(steel(1e3, 2e3));
  EXPECT_EQ(m.stateSize(), 13);
  const J2State s = zeroState(m);
  for (double v : s)
    EXPECT_EQ(v, 0.0);
  J2State t = s;
  t[12] = 0.25;
  EXPECT_EQ(m.equivalentPlasticStrain(t.data()), 0.25);
}

TEST(J2SmallStrain, TangentMatchesCentralDifferencesInElasticSteps) {
  const J2SmallStrain m(steel(10e3, 5e3));
  const double yieldStrain = 250.0 / 200e3;
  std::mt19937 gen(11);
  for (int sample = 0; sample < 10; ++sample) {
    const Voigt eps = randomStrain(gen, 0.4 * yieldStrain, sample % 2 == 1);
    const J2State s0 = zeroState(m);
    const J2Result r = evaluateJ2(m, eps, s0);
    EXPECT_EQ(r.state, s0) << "elastic step changed the state";
    EXPECT_LT(tangentError(m, eps, s0), 1e-6) << sample;
  }
}

// A state that has yielded once (both hardenings active) and the strain that produced it.
struct Yielded {
  Voigt strain;
  J2State state;
};

Yielded yieldOnce(const J2SmallStrain& m, std::mt19937& gen, bool planeStrain) {
  const double yieldStrain =
      m.parameters().yieldStress.at(20.0) / m.parameters().youngModulus.at(20.0);
  Yielded y;
  y.strain = randomStrain(gen, 4 * yieldStrain, planeStrain);
  y.state = evaluateJ2(m, y.strain, zeroState(m)).state;
  EXPECT_GT(y.state[J2SmallStrain::kEquivalentPlasticStrain], 0.0);
  return y;
}

TEST(J2SmallStrain, TangentMatchesCentralDifferencesInPlasticLoading) {
  const J2SmallStrain m(steel(10e3, 5e3));
  const double yieldStrain = 250.0 / 200e3;
  std::mt19937 gen(12);
  for (int sample = 0; sample < 12; ++sample) {
    const bool planeStrain = sample % 3 == 2;
    const Yielded y = yieldOnce(m, gen, planeStrain);
    // Continue loading along the previous direction plus a random change of direction.
    Voigt eps = add(y.strain, y.strain, 0.3);
    eps = add(eps, randomStrain(gen, yieldStrain, planeStrain));
    const J2Result r = evaluateJ2(m, eps, y.state);
    ASSERT_GT(r.state[12], y.state[12] + 1e-5) << sample << ": the step is not plastic";
    EXPECT_LT(tangentError(m, eps, y.state), 1e-6) << sample;
  }
}

// The consistent tangent of the radial return (isotropic and kinematic hardening) is symmetric:
// the assembled tangent is, so the linear solver may take it as such (mumps Mode: automatic).
TEST(J2SmallStrain, TangentIsSymmetricInPlasticLoading) {
  const J2SmallStrain m(steel(10e3, 5e3));
  const double yieldStrain = 250.0 / 200e3;
  std::mt19937 gen(13);
  for (int sample = 0; sample < 12; ++sample) {
    const bool planeStrain = sample % 3 == 2;
    const Yielded y = yieldOnce(m, gen, planeStrain);
    const Voigt eps =
        add(add(y.strain, y.strain, 0.3), randomStrain(gen, yieldStrain, planeStrain));
    const J2Result r = evaluateJ2(m, eps, y.state);
    ASSERT_GT(r.state[12], y.state[12] + 1e-5) << sample << ": the step is not plastic";
    double scale = 0.0, asymmetry = 0.0;
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b) {
        scale = std::max(scale, std::abs(r.tangent[a * 6 + b]));
        asymmetry = std::max(asymmetry, std::abs(r.tangent[a * 6 + b] - r.tangent[b * 6 + a]));
      }
    EXPECT_LT(asymmetry, 1e-12 * scale) << sample;
  }
}

TEST(J2SmallStrain, TangentMatchesCentralDifferencesWithoutHardening) {
  // Perfect plasticity from the virgin state: the first step of every plastic scene.
  const J2SmallStrain m(steel(0.0, 0.0));
  const double yieldStrain = 250.0 / 200e3;
  std::mt19937 gen(14);
  for (int sample = 0; sample < 12; ++sample) {
    const bool planeStrain = sample % 2 == 1;
    const Voigt eps = randomStrain(gen, 5 * yieldStrain, planeStrain);
    const J2Result r = evaluateJ2(m, eps, zeroState(m));
    ASSERT_GT(r.state[12], 0.0) << sample << ": the step is not plastic";
    EXPECT_LT(tangentError(m, eps, zeroState(m)), 1e-6) << sample;
  }
}

TEST(J2SmallStrain, TangentMatchesCentralDifferencesInUnloading) {
  const J2SmallStrain m(steel(10e3, 5e3));
  const double mu = m.mu();
  std::mt19937 gen(13);
  for (int sample = 0; sample < 10; ++sample) {
    const bool planeStrain = sample % 2 == 1;
    const Yielded y = yieldOnce(m, gen, planeStrain);
    const J2Result atYield = evaluateJ2(m, y.strain, y.state);
    // Strain step -c xi (engineering shears), 2 mu c = 1/2: xi halves, f = -(yield stress) / 2.
    const double p = (atYield.stress[0] + atYield.stress[1] + atYield.stress[2]) / 3;
    Voigt eps = y.strain;
    for (int a = 0; a < 6; ++a) {
      const double xi = atYield.stress[a] - (a < 3 ? p : 0.0) - y.state[6 + a];
      eps[a] -= (a < 3 ? 1.0 : 2.0) * xi / (4 * mu);
    }
    const J2Result r = evaluateJ2(m, eps, y.state);
    EXPECT_EQ(r.state, y.state) << sample << ": unloading changed the state";
    EXPECT_LT(tangentError(m, eps, y.state), 1e-6) << sample;
    // The unloading tangent is the elastic one.
    const J2Result e = evaluateJ2(m, Voigt{}, zeroState(m));
    for (int a = 0; a < 36; ++a)
      EXPECT_NEAR(r.tangent[a], e.tangent[a], 1e-9 * 200e3);
  }
}

TEST(J2SmallStrain, StressStaysOnTheYieldSurfaceAfterAPlasticStep) {
  const double Hiso = 10e3, Hkin = 5e3;
  const J2SmallStrain m(steel(Hiso, Hkin));
  std::mt19937 gen(14);
  for (int sample = 0; sample < 10; ++sample) {
    const Yielded y = yieldOnce(m, gen, false);
    const Voigt eps = add(y.strain, randomStrain(gen, 3 * 250.0 / 200e3, false));
    const J2Result r = evaluateJ2(m, eps, y.state);
    const double p = r.state[12];
    if (p == y.state[12]) continue;  // an elastic step: nothing to check
    EXPECT_NEAR(relativeMises(r.stress, r.state), 250.0 + Hiso * p, 1e-10 * 250.0) << sample;
    // Plastic incompressibility, deviatoric back stress, Prager's rule alpha = 2/3 H_kin eps_p
    // (tensor components: engineering shears halved) from a zero initial state.
    EXPECT_NEAR(r.state[0] + r.state[1] + r.state[2], 0.0, 1e-15);
    EXPECT_NEAR(r.state[6] + r.state[7] + r.state[8], 0.0, 1e-9);
    for (int a = 0; a < 6; ++a)
      EXPECT_NEAR(r.state[6 + a], 2.0 / 3.0 * Hkin * r.state[a] * (a < 3 ? 1.0 : 0.5), 1e-9);
  }
}

TEST(J2SmallStrain, UniaxialStressFollowsTheBilinearClosedFormAndUnloadsWithSlopeE) {
  const double E = 200e3, sy = 250.0;
  for (auto [Hiso, Hkin] : {std::pair{20e3, 0.0}, std::pair{15e3, 5e3}}) {
    const J2SmallStrain m(steel(Hiso, Hkin));
    const double H = Hiso + Hkin;
    J2State state = zeroState(m);
    Voigt strain{};
    double sigmaMax = 0, epsMax = 0;
    for (int step = 1; step <= 40; ++step) {
      const double eps = 0.01 * step / 40;
      const J2Result r = uniaxialStep(m, eps, state, strain);
      const double expected = eps <= sy / E ? E * eps : sy + E * H / (E + H) * (eps - sy / E);
      EXPECT_NEAR(r.stress[0], expected, 1e-9 * sy) << "eps = " << eps;
      if (eps > sy / E) {
        EXPECT_NEAR(r.state[12], (r.stress[0] - sy) / H, 1e-10) << "eps = " << eps;
      }
      state = r.state;
      sigmaMax = r.stress[0];
      epsMax = eps;
    }
    // Unloading by 0.001 (elastic range is at least 2 sigma_y wide): slope E, no plastic flow.
    const J2Result r = uniaxialStep(m, epsMax - 0.001, state, strain);
    EXPECT_NEAR(r.stress[0], sigmaMax - E * 0.001, 1e-9 * sy);
    EXPECT_EQ(r.state[12], state[12]);
  }
}

TEST(J2SmallStrain, KinematicHardeningReverseYieldIsBauschinger) {
  const double E = 200e3, sy = 250.0, H = 20e3, epsMax = 0.005;
  // Reverse yield at sigma_max - 2 sigma_y with kinematic hardening; at -sigma_max with
  // isotropic hardening (the contrast shows the back stress, not the elastic range, moves).
  for (bool kinematic : {true, false}) {
    const J2SmallStrain m(steel(kinematic ? 0.0 : H, kinematic ? H : 0.0));
    J2State state = zeroState(m);
    Voigt strain{};
    J2Result loaded;
    for (int step = 1; step <= 10; ++step) {
      loaded = uniaxialStep(m, epsMax * step / 10, state, strain);
      state = loaded.state;
    }
    const double sigmaMax = loaded.stress[0];
    EXPECT_NEAR(sigmaMax, sy + E * H / (E + H) * (epsMax - sy / E), 1e-9 * sy);
    const double delta = 1e-3 * sy;
    // Just short of sigma_max - 2 sigma_y: elastic.
    Voigt s1 = strain;
    const J2Result before = uniaxialStep(m, epsMax - (2 * sy - delta) / E, state, s1);
    EXPECT_NEAR(before.stress[0], sigmaMax - 2 * sy + delta, 1e-9 * sy);
    EXPECT_EQ(before.state[12], state[12]);
    // Just past it: plastic with kinematic hardening, still elastic with isotropic hardening.
    Voigt s2 = strain;
    const J2Result after = uniaxialStep(m, epsMax - (2 * sy + delta) / E, state, s2);
    if (kinematic) {
      EXPECT_GT(after.state[12], state[12]);
      // Further reverse loading follows the hardening slope from sigma_max - 2 sigma_y.
      Voigt s3 = strain;
      const double epsReverse = epsMax - 2 * sy / E;
      const J2Result further = uniaxialStep(m, epsReverse - 0.002, state, s3);
      EXPECT_NEAR(further.stress[0], sigmaMax - 2 * sy - E * H / (E + H) * 0.002, 1e-9 * sy);
    } else {
      EXPECT_EQ(after.state[12], state[12]);
      Voigt s3 = strain;
      const J2Result atMinus = uniaxialStep(m, epsMax - (2 * sigmaMax - delta) / E, state, s3);
      EXPECT_EQ(atMinus.state[12], state[12]);
      Voigt s4 = strain;
      const J2Result pastMinus = uniaxialStep(m, epsMax - (2 * sigmaMax + delta) / E, state, s4);
      EXPECT_GT(pastMinus.state[12], state[12]);
    }
  }
}

TEST(J2SmallStrain, PurePressureNeverYields) {
  const J2SmallStrain m(steel(10e3, 5e3));
  const double K = 200e3 / (3 * (1 - 2 * 0.3));
  std::mt19937 gen(15);
  const Yielded y = yieldOnce(m, gen, false);
  const J2Result atYield = evaluateJ2(m, y.strain, y.state);
  for (double e : {-0.05, -1e-3, 1e-3, 0.05}) {
    const Voigt hydrostatic = {e, e, e, 0, 0, 0};
    // From the virgin state.
    const J2Result r0 = evaluateJ2(m, hydrostatic, zeroState(m));
    EXPECT_EQ(r0.state, zeroState(m)) << e;
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(r0.stress[a], 3 * K * e, 1e-9 * std::abs(3 * K * e)) << e;
    // From a state on the yield surface: the pressure changes, nothing else.
    const J2Result r1 = evaluateJ2(m, add(y.strain, hydrostatic), y.state);
    EXPECT_EQ(r1.state, y.state) << e;
    for (int a = 0; a < 6; ++a)
      EXPECT_NEAR(r1.stress[a], atYield.stress[a] + (a < 3 ? 3 * K * e : 0.0), 1e-8 * 250.0) << e;
  }
}
}  // namespace
}  // namespace contactlab
