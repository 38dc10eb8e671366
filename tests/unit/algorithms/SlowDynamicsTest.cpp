// The slow-dynamics regularization as the algorithm owns it: the coefficient alpha / (T dt)^2,
// the implicit Euler predictor u* = u_n + dt v_n from the last two converged states (at rest
// before the first), the term removed after each converged step and after the run, and a
// system without a mass refused before anything runs.
#include "algorithms/SlowDynamics.hpp"
#include "algorithms/StaticSolver.hpp"
#include "base/InputError.hpp"

#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>

namespace contactlab {
namespace {

// Two unknowns whose step solution is x = (t, 2 t); records every inertia it is handed.
class RecordingSystem : public NonlinearSystem {
 public:
  explicit RecordingSystem(std::string missingMass = "")
      : missingMass_(std::move(missingMass)),
        map_(Teuchos::rcp(new Map(2, 0, Tpetra::getDefaultComm()))) {}
  std::vector<InertiaTerm> terms;

  Teuchos::RCP<Vector> createVector() const override { return Teuchos::rcp(new Vector(map_)); }
  void applyDirichlet(double, Vector&) const override {}
  void assemble(const Vector&, double, Vector* residual, bool) override {
    if (residual) residual->putScalar(0.0);
  }
  const Teuchos::RCP<Matrix>& tangent() const override { return tangent_; }
  void commitState(const Vector&, double) override {}
  std::string massUnavailable() const override { return missingMass_; }
  void setInertia(const InertiaTerm& inertia) override { terms.push_back(inertia); }

 private:
  std::string missingMass_;
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<Matrix> tangent_;
};

Teuchos::RCP<Vector> state(const RecordingSystem& system, double a, double b) {
  auto v = system.createVector();
  if (v->getLocalLength() == 2) {
    v->getDataNonConst(0)[0] = a;
    v->getDataNonConst(0)[1] = b;
  }
  return v;
}

SlowDynamicsOptions enabled(bool inResidual = true) {
  SlowDynamicsOptions o;
  o.enabled = true;
  o.alpha = 0.7;
  o.timeScale = 0.5;
  o.inertiaInResidual = inResidual;
  return o;
}

TEST(SlowDynamics, CoefficientIsAlphaOverTheSquaredPhysicalStep) {
  EXPECT_DOUBLE_EQ(enabled().coefficient(0.2), 0.7 / (0.1 * 0.1));
  EXPECT_EQ(enabled().coefficient(0.0), 0.0);
  EXPECT_EQ(SlowDynamicsOptions{}.coefficient(0.2), 0.0);  // disabled
}

TEST(SlowDynamics, PredictorStartsAtRestThenFollowsTheLastVelocity) {
  RecordingSystem system;
  SlowDynamics sd(enabled());
  sd.start(*state(system, 0, 0), 0.0);
  sd.beginStep(system, 0.1);
  ASSERT_EQ(system.terms.size(), 1u);
  EXPECT_DOUBLE_EQ(system.terms[0].coefficient, 0.7 / (0.05 * 0.05));
  EXPECT_EQ(system.terms[0].reference->normInf(), 0.0);  // at rest: u* = u_0

  sd.commit(system, *state(system, 1, 2), 0.1);
  EXPECT_EQ(system.terms.back().coefficient, 0.0);  // static between steps
  sd.commit(system, *state(system, 3, 1), 0.3);
  // u* = u_2 + (0.15 / 0.2) (u_2 - u_1) for a step to 0.45 (0.45 - 0.3 rounds: near, not equal).
  auto star = sd.predictor(0.45);
  if (star->getLocalLength() == 2) {
    EXPECT_NEAR(star->getData(0)[0], 3 + 0.75 * (3 - 1), 1e-14);
    EXPECT_NEAR(star->getData(0)[1], 1 + 0.75 * (1 - 2), 1e-14);
  }
  sd.beginStep(system, 0.45);
  EXPECT_DOUBLE_EQ(system.terms.back().coefficient, 0.7 / (0.075 * 0.075));
}

TEST(SlowDynamics, TangentOnlyHasNoReference) {
  RecordingSystem system;
  SlowDynamics sd(enabled(false));
  sd.start(*state(system, 0, 0), 0.0);
  sd.beginStep(system, 0.5);
  ASSERT_EQ(system.terms.size(), 1u);
  EXPECT_GT(system.terms[0].coefficient, 0.0);
  EXPECT_TRUE(system.terms[0].reference.is_null());
}

TEST(SlowDynamics, DisabledNeverTouchesTheSystem) {
  RecordingSystem system("no mass here");
  SlowDynamics sd{SlowDynamicsOptions{}};
  sd.requireMass(system);
  sd.start(*state(system, 0, 0), 0.0);
  sd.beginStep(system, 0.5);
  sd.commit(system, *state(system, 1, 1), 0.5);
  EXPECT_TRUE(system.terms.empty());
}

TEST(SlowDynamics, SystemWithoutMassIsRefusedWithItsReason) {
  RecordingSystem system("the material of block 'b' has density 0");
  try {
    SlowDynamics(enabled()).requireMass(system);
    FAIL() << "a system without a mass was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("block 'b' has density 0"), std::string::npos);
  }
}

// Steps whose Newton solves at once: the inertia is in effect during each step and removed
// after every converged step and after the run.
class ImmediateNewton : public NewtonMethod {
 public:
  explicit ImmediateNewton(RecordingSystem& system) : system_(system) {}
  std::vector<double> coefficients;  // in effect at each solve
  NewtonOutcome solve(Vector&, const NewtonRequest&, const Observer&) override {
    coefficients.push_back(system_.terms.back().coefficient);
    NewtonOutcome out;
    return out;
  }

 private:
  RecordingSystem& system_;
};

TEST(SlowDynamics, StaticSolverAppliesItPerStepAndEndsStatic) {
  RecordingSystem system;
  ImmediateNewton newton(system);
  StaticSolverOptions options;
  options.steps = 2;
  options.slowDynamics = enabled();
  auto u = system.createVector();
  const RunReport report = StaticSolver(system, nullptr, newton, options).run(*u, {});
  ASSERT_TRUE(report.converged) << report.message;
  ASSERT_EQ(newton.coefficients.size(), 2u);
  for (double c : newton.coefficients)
    EXPECT_DOUBLE_EQ(c, 0.7 / (0.25 * 0.25));  // dt = 0.5, T = 0.5
  EXPECT_EQ(system.terms.back().coefficient, 0.0);

  RecordingSystem massless("the material of block 'b' has density 0");
  EXPECT_THROW(StaticSolver(massless, nullptr, newton, options), InputError);
}

}  // namespace
}  // namespace contactlab
