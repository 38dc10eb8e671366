// StaticSolver with a forced cycling treatment: a state that the forced (modified) contact law
// accepts is a solution only if the model's own law holds there too. A one-unknown system with
// one contact point: R(x) = x - 1 while the point is forced closed, R(x) = x - natural with
// the law restored; a scripted Newton cycles the point's zone 1, 3, 1, 3 (sub-cycling 1, which
// the forced treatment closes) and then solves whatever residual is in effect.
#include "algorithms/StaticSolver.hpp"

#include <Tpetra_Core.hpp>

#include <gtest/gtest.h>
#include <vector>

namespace contactlab {
namespace {

class OnePointSystem : public NonlinearSystem, public ContactControls {
 public:
  explicit OnePointSystem(double natural)
      : natural_(natural), map_(Teuchos::rcp(new Map(1, 0, Tpetra::getDefaultComm()))) {}

  double root() const { return forced_ ? 1.0 : natural_; }
  int zone = 1;
  bool forced() const { return forced_; }

  // NonlinearSystem
  Teuchos::RCP<Vector> createVector() const override { return Teuchos::rcp(new Vector(map_)); }
  void applyDirichlet(double, Vector&) const override {}
  void assemble(const Vector& x, double, Vector* residual, bool) override {
    if (residual) residual->getDataNonConst(0)[0] = x.getData(0)[0] - root();
  }
  const Teuchos::RCP<Matrix>& tangent() const override { return tangent_; }
  void commitState(const Vector&, double) override {}

  // ContactControls
  void freezeStatuses(bool) override {}
  void freezeThresholds(bool) override {}
  std::vector<StatusChange> statusUpdate(const Vector&, double) override { return {}; }
  void applyStatuses(const std::vector<StatusChange>&) override {}
  double updateThresholds(const Vector&, double) override { return 0; }
  int statusChanges() const override { return 0; }
  std::vector<ContactPointState> pointStates() const override {
    ContactPointState s;
    s.zone = zone;
    s.status = zone >= 3 ? 1 : 0;
    s.gap = zone == 1 ? 1e-3 : -1e-3;
    s.length = 1;
    return {s};
  }
  void forceStatus(std::size_t, int status) override { forced_ = status == kForcedClosed; }
  bool scaleCoefficients(std::size_t, double) override { return false; }
  void releaseTreatments() override { forced_ = false; }
  void releaseForcedStatuses() override { forced_ = false; }
  void seedInitialStatuses(Vector&, double) override {}
  void markCycling(std::size_t, int) override {}
  void setFrictionScale(double) override {}
  void setGeometricTerms(GeometricTerms) override {}

 private:
  double natural_;
  bool forced_ = false;
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<Matrix> tangent_;
};

// Solve 1 cycles (zones 1, 3, 1, 3) and then solves; later solves solve at once, or fail when
// `naturalFails` and the law is not forced.
class ScriptedNewton : public NewtonMethod {
 public:
  ScriptedNewton(OnePointSystem& system, bool naturalFails)
      : system_(system), naturalFails_(naturalFails) {}
  int solves = 0;

  NewtonOutcome solve(Vector& x, const NewtonRequest&, const Observer& observer) override {
    NewtonOutcome out;
    if (solves++ == 0)
      for (int zone : {1, 3, 1, 3}) {
        system_.zone = zone;
        lawChanged.push_back(observer.treat(++out.iterations));
        observer.report(out.iterations, 1.0);
      }
    if (naturalFails_ && !system_.forced()) {
      out.failure = "max-iterations";
      out.message = "scripted";
      return out;
    }
    x.getDataNonConst(0)[0] = system_.root();
    lawChanged.push_back(observer.treat(++out.iterations));
    observer.report(out.iterations, 0.0);
    return out;
  }
  std::vector<bool> lawChanged;  // what the observer returned at each iterate

 private:
  OnePointSystem& system_;
  bool naturalFails_;
};

// One load step with the forced treatment from u = 0; u holds the converged state.
RunReport runForced(OnePointSystem& system, ScriptedNewton& newton, Vector& u,
                    const StaticSolver::IterationCallback& onIteration = {}) {
  StaticSolverOptions options;
  options.cyclingTreatment = "forced";
  StaticSolver solver(system, &system, newton, options);
  return solver.run(u, {}, onIteration);
}

TEST(StaticSolverForcedTreatment, AStateThatTheModelsLawAcceptsConverges) {
  OnePointSystem system(/*natural=*/1.0);
  ScriptedNewton newton(system, /*naturalFails=*/true);
  auto u = system.createVector();
  const RunReport report = runForced(system, newton, *u);
  EXPECT_TRUE(report.converged) << report.failure << ": " << report.message;
  EXPECT_EQ(newton.solves, 1);
  EXPECT_EQ(report.cycling[static_cast<int>(CyclingKind::SubCycling1)], 1);
}

// The observer says when its treatment changed the law (Newton then evaluates the iterate
// again): at the fourth iterate, where the cycle is detected and the point forced, only.
TEST(StaticSolverForcedTreatment, TheObserverSaysWhenTheTreatmentChangedTheLaw) {
  OnePointSystem system(/*natural=*/1.0);
  ScriptedNewton newton(system, /*naturalFails=*/true);
  auto u = system.createVector();
  ASSERT_TRUE(runForced(system, newton, *u).converged);
  EXPECT_EQ(newton.lawChanged, (std::vector<bool>{false, false, false, true, false}));
}

// The progress of each iterate says at which the treatment changed the law, and at how many
// points (a progress line notes it: the residual jumps there).
TEST(StaticSolverForcedTreatment, TheProgressNamesTheTreatedIterate) {
  OnePointSystem system(/*natural=*/1.0);
  ScriptedNewton newton(system, /*naturalFails=*/true);
  auto u = system.createVector();
  std::vector<int> treated;
  ASSERT_TRUE(runForced(system, newton, *u, [&](const StaticSolver::IterateProgress& p) {
                EXPECT_EQ(p.step, 1);
                EXPECT_STREQ(p.attempt, "");
                treated.push_back(p.treatedPoints);
              }).converged);
  EXPECT_EQ(treated, (std::vector<int>{0, 0, 0, 1, 0}));
}

TEST(StaticSolverForcedTreatment, AViolatingStateIsSolvedAgainWithTheLawRestored) {
  OnePointSystem system(/*natural=*/2.0);
  ScriptedNewton newton(system, /*naturalFails=*/false);
  auto u = system.createVector();
  const RunReport report = runForced(system, newton, *u);
  ASSERT_TRUE(report.converged) << report.failure << ": " << report.message;
  EXPECT_EQ(newton.solves, 2);
  EXPECT_DOUBLE_EQ(u->getData(0)[0], 2.0);  // the model's solution, not the forced one
}

TEST(StaticSolverForcedTreatment, AViolatingStateThatNewtonCannotLeaveIsNamed) {
  OnePointSystem system(/*natural=*/2.0);
  ScriptedNewton newton(system, /*naturalFails=*/true);
  auto u = system.createVector();
  const RunReport report = runForced(system, newton, *u);
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.failure, "degraded-contact");
  EXPECT_NE(report.message.find("contact points 0"), std::string::npos) << report.message;
  EXPECT_NE(report.message.find("max-iterations"), std::string::npos) << report.message;
}

// A point forced closed holds the friction threshold it had when forced, and the threshold
// fixed point's frozen value keeps it through its updates. Once the forcing is released the
// thresholds are read from the law again, and a threshold that moves means the forced state is
// not a solution: Newton goes on (the ironing under penalty and the fixed point ended with a
// stick traction of 3.6 mu p otherwise).
class ThresholdsMoveOnceReleased : public OnePointSystem {
 public:
  ThresholdsMoveOnceReleased() : OnePointSystem(/*natural=*/1.0) {}
  int thresholdUpdates = 0;
  double updateThresholds(const Vector&, double) override {
    // The first update runs with the point forced; the second, once it is released, moves.
    return ++thresholdUpdates == 2 ? 0.5 : 0.0;
  }
};

TEST(StaticSolverForcedTreatment, ThresholdsHeldByTheForcingAreReadFromTheLawOnRelease) {
  ThresholdsMoveOnceReleased system;
  ScriptedNewton newton(system, /*naturalFails=*/false);
  StaticSolverOptions options;
  options.cyclingTreatment = "forced";
  options.statusesInNewton = false;
  options.thresholdsInNewton = false;
  StaticSolver solver(system, &system, newton, options);
  auto u = system.createVector();
  const RunReport report = solver.run(*u, {});
  ASSERT_TRUE(report.converged) << report.failure << ": " << report.message;
  EXPECT_EQ(newton.solves, 2);  // once forced, once more from the released state
  EXPECT_EQ(system.thresholdUpdates, 3);
}

// Fails the first attempt at every step and solves the retry: each step converges only after
// a cut, so the step never grows back. After 100 solves it solves everything (the bound that
// lets a run without the floor end instead of creeping towards t = 1 forever).
class FailsEveryFirstAttempt : public NewtonMethod {
 public:
  explicit FailsEveryFirstAttempt(OnePointSystem& system) : system_(system) {}
  int solves = 0;

  NewtonOutcome solve(Vector& x, const NewtonRequest&, const Observer&) override {
    NewtonOutcome out;
    out.iterations = 1;
    if (++solves % 2 == 1 && solves < 100) {
      out.failure = "max-iterations";
      out.message = "scripted";
      return out;
    }
    x.getDataNonConst(0)[0] = system_.root();
    return out;
  }

 private:
  OnePointSystem& system_;
};

TEST(StaticSolverStepCuts, NoStepIsCutBelowTheSmallestMaxCutsAllows) {
  OnePointSystem system(/*natural=*/1.0);
  FailsEveryFirstAttempt newton(system);
  StaticSolverOptions options;
  options.maxCuts = 3;  // smallest step 1/8
  StaticSolver solver(system, &system, newton, options);
  auto u = system.createVector();
  const RunReport report = solver.run(*u, {});
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.failure, "step-too-small");
  EXPECT_NE(report.message.find("the smallest step"), std::string::npos) << report.message;
  // Steps to 1/2, 3/4 and 7/8 converge after one cut each; the next would need dt = 1/16.
  EXPECT_EQ(report.steps, 3);
  EXPECT_EQ(newton.solves, 7);
}

}  // namespace
}  // namespace contactlab
