// StaticSolver's load stepping around a failing Newton. The line-search retry (Newton/Line
// Search Retry): a step whose Newton failed with full steps is solved again from the step's
// start by the retry Newton, at the last try ('last-resort') or before every cut
// ('every-failure'); never for a failure a line search cannot change (a singular tangent).
// Landing: whatever cuts did to the step size, a step ends on every nominal time k End Time /
// Steps and every landing time (a load table's kink) it would pass. A one-unknown system
// R(x) = x - t; the scripted Newtons either fail with a given reason or put x at the root.
#include "algorithms/StaticSolver.hpp"
#include "core/io/ParameterValidation.hpp"

#include <Tpetra_Core.hpp>

#include <algorithm>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace contactlab {
namespace {

class RootAtTimeSystem : public NonlinearSystem {
 public:
  RootAtTimeSystem() : map_(Teuchos::rcp(new Map(1, 0, Tpetra::getDefaultComm()))) {}
  Teuchos::RCP<Vector> createVector() const override { return Teuchos::rcp(new Vector(map_)); }
  void applyDirichlet(double, Vector&) const override {}
  void assemble(const Vector& x, double t, Vector* residual, bool) override {
    if (residual) residual->getDataNonConst(0)[0] = x.getData(0)[0] - t;
  }
  const Teuchos::RCP<Matrix>& tangent() const override { return tangent_; }
  void commitState(const Vector&, double) override {}

 private:
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<Matrix> tangent_;
};

// Fails with `failure` (three iterations), or solves in one when `failure` is empty.
// With `failAt`, fails only at the first solve of each of those times.
class ScriptedNewton : public NewtonMethod {
 public:
  explicit ScriptedNewton(std::string failure, std::vector<double> failAt = {})
      : failure_(std::move(failure)), failAt_(std::move(failAt)), always_(failAt_.empty()) {}
  int solves = 0;
  std::vector<double> times;       // of the solves
  std::vector<int> maxIterations;  // of the solves' requests
  NewtonOutcome solve(Vector& x, const NewtonRequest& request, const Observer& observer) override {
    ++solves;
    times.push_back(request.time);
    maxIterations.push_back(request.maxIterations);
    if (observer.report) observer.report(0, 1.0);  // the start, for the progress
    NewtonOutcome out;
    const auto at = std::find(failAt_.begin(), failAt_.end(), request.time);
    const bool succeed = failure_.empty() || (!always_ && at == failAt_.end());
    if (at != failAt_.end()) failAt_.erase(at);
    if (succeed) {
      x.putScalar(request.time);
      out.iterations = 1;
      return out;
    }
    out.iterations = 3;
    out.failure = failure_;
    out.message = "scripted " + failure_;
    return out;
  }

 private:
  std::string failure_;
  std::vector<double> failAt_;
  bool always_;  // fails at every solve
};

StaticSolverOptions options(const std::string& retry, int maxCuts) {
  StaticSolverOptions o;
  o.steps = 2;
  o.maxCuts = maxCuts;
  o.lineSearchRetry = retry;
  return o;
}

// `retried`, when given, gets each converged step's StepReport::lineSearchRetry; `attempts`
// each iterate's IterateProgress::attempt.
RunReport run(NewtonMethod& first, NewtonMethod& retry, const StaticSolverOptions& o,
              std::vector<bool>* retried = nullptr, std::vector<std::string>* attempts = nullptr) {
  RootAtTimeSystem system;
  auto u = system.createVector();
  return StaticSolver(system, nullptr, first, o, nullptr, &retry)
      .run(
          *u,
          [&](const StepReport& sr, const Vector&) {
            if (retried) retried->push_back(sr.lineSearchRetry);
          },
          [&](const StaticSolver::IterateProgress& p) {
            if (attempts) attempts->push_back(p.attempt);
          });
}

TEST(LineSearchRetry, ALastResortSolvesTheStepTheFullStepsFailed) {
  ScriptedNewton fullSteps("max-iterations"), lineSearch("");
  std::vector<bool> retried;
  const RunReport report = run(fullSteps, lineSearch, options("last-resort", 0), &retried);
  ASSERT_TRUE(report.converged) << report.message;
  EXPECT_TRUE(report.failure.empty());
  EXPECT_EQ(retried, (std::vector<bool>{true, true}));  // what the progress line reports
  EXPECT_EQ(report.steps, 2);
  EXPECT_EQ(report.lineSearchRetries, 2);
  EXPECT_EQ(lineSearch.solves, 2);
  EXPECT_EQ(report.iterations, 2 * (3 + 1));  // both attempts count
}

// A progress line says which attempt at a step its iterate belongs to.
TEST(LineSearchRetry, TheProgressNamesTheRetrysIterates) {
  ScriptedNewton fullSteps("max-iterations"), lineSearch("");
  std::vector<std::string> attempts;
  ASSERT_TRUE(run(fullSteps, lineSearch, options("last-resort", 0), nullptr, &attempts).converged);
  EXPECT_EQ(attempts, (std::vector<std::string>{"", "line-search retry", "", "line-search retry"}));
}

// The retry's halved steps take more iterations than full steps, and the cut it saves costs the
// whole step again: it may take Line Search Retry Max Iterations, twice Max Iterations by
// default (with Max Iterations, the hex8 tube's retries stopped 2e-4 from converging and cut).
TEST(LineSearchRetry, TheRetryMayTakeTwiceMaxIterations) {
  Teuchos::ParameterList newton = *StaticSolverOptions::validNewton();
  newton.set("Max Iterations", 12);
  const auto from = [&] {
    return StaticSolverOptions::from(*StaticSolverOptions::validLoadSteps(), newton,
                                     *StaticSolverOptions::validAlgorithm());
  };
  StaticSolverOptions o = from();
  EXPECT_EQ(o.retryMaxIterations, 24);
  newton.set("Line Search Retry Max Iterations", 30);
  EXPECT_EQ(from().retryMaxIterations, 30);
  newton.set("Line Search Retry Max Iterations", -1);
  EXPECT_THROW(from(), std::invalid_argument);

  ScriptedNewton fullSteps("max-iterations"), lineSearch("");
  o.steps = 1;
  o.maxCuts = 0;
  ASSERT_TRUE(run(fullSteps, lineSearch, o).converged);
  EXPECT_EQ(fullSteps.maxIterations, (std::vector<int>{12}));
  EXPECT_EQ(lineSearch.maxIterations, (std::vector<int>{24}));
}

TEST(LineSearchRetry, ALastResortWaitsUntilTheStepCannotBeCut) {
  ScriptedNewton fullSteps("diverged"), lineSearch("");
  const RunReport report = run(fullSteps, lineSearch, options("last-resort", 2));
  ASSERT_TRUE(report.converged) << report.message;
  // The first step (0.5) is cut twice before its retry, at the smallest step 0.5 / 2^2.
  ASSERT_FALSE(lineSearch.times.empty());
  EXPECT_DOUBLE_EQ(lineSearch.times[0], 0.125);
  EXPECT_EQ(std::vector<double>(fullSteps.times.begin(), fullSteps.times.begin() + 3),
            (std::vector<double>{0.5, 0.25, 0.125}));
  // Every failure is either cut or, at the last try, retried.
  EXPECT_EQ(fullSteps.solves, report.cuts + report.lineSearchRetries);
  EXPECT_EQ(lineSearch.solves, report.lineSearchRetries);
}

TEST(LineSearchRetry, EveryFailureRetriesBeforeCutting) {
  ScriptedNewton fullSteps("degraded-contact"), lineSearch("");
  const RunReport report = run(fullSteps, lineSearch, options("every-failure", 2));
  ASSERT_TRUE(report.converged) << report.message;
  EXPECT_EQ(report.cuts, 0);
  EXPECT_EQ(report.lineSearchRetries, 2);
}

TEST(LineSearchRetry, NeverLeavesTheFailure) {
  ScriptedNewton fullSteps("max-iterations"), lineSearch("");
  const RunReport report = run(fullSteps, lineSearch, options("never", 0));
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.failure, "max-iterations");
  EXPECT_EQ(lineSearch.solves, 0);
  EXPECT_EQ(report.lineSearchRetries, 0);
}

TEST(LineSearchRetry, ASingularTangentIsNotRetried) {
  ScriptedNewton fullSteps(kSingularTangent), lineSearch("");
  const RunReport report = run(fullSteps, lineSearch, options("last-resort", 0));
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.failure, kSingularTangent);
  EXPECT_EQ(lineSearch.solves, 0);
}

// An iterate the system could not evaluate (an element inverted, a mortar facet without a dual
// basis) is retried: NOX's backtracking shortens a step into such a point
// (UnevaluableIterate.NoxBacktrackingShortensAStepIntoTheUnevaluableRegion).
TEST(LineSearchRetry, AnUnevaluableIterateIsRetried) {
  for (const char* failure :
       {"nan-detected", "contact-geometry-failed", "inverted-element", "material-update-failed"}) {
    ScriptedNewton fullSteps(failure), lineSearch("");
    const RunReport report = run(fullSteps, lineSearch, options("last-resort", 0));
    EXPECT_TRUE(report.converged) << failure;
    EXPECT_EQ(lineSearch.solves, 2) << failure;
  }
}

TEST(LineSearchRetry, AFailedRetryNamesBothAttempts) {
  ScriptedNewton fullSteps("max-iterations"), lineSearch("diverged");
  const RunReport report = run(fullSteps, lineSearch, options("last-resort", 0));
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.failure, "max-iterations");  // the method's own
  EXPECT_EQ(report.message.find("scripted max-iterations"), 0u) << report.message;
  EXPECT_NE(report.message.find("solved again with the Backtrack line search: diverged: "
                                "scripted diverged"),
            std::string::npos)
      << report.message;
  EXPECT_EQ(report.lineSearchRetries, 1);
}

// The times of the converged steps of a run of `o` on RootAtTimeSystem.
std::vector<double> convergedTimes(NewtonMethod& newton, const StaticSolverOptions& o) {
  RootAtTimeSystem system;
  auto u = system.createVector();
  std::vector<double> converged;
  const RunReport report =
      StaticSolver(system, nullptr, newton, o).run(*u, [&](const StepReport& sr, const Vector&) {
        converged.push_back(sr.time);
      });
  EXPECT_TRUE(report.converged) << report.message;
  return converged;
}

// The step to 0.25 fails twice: cut to 0.125, then from there to 0.1875; the steps regrow
// (0.0625, 0.125, 0.25), and the one from 0.375 would end at 0.625, past the nominal time 0.5
// and a table's peak at 0.55: the steps land on both.
TEST(LoadStepping, StepsLandOnTheNominalTimesAndTheLandingTimes) {
  ScriptedNewton newton("max-iterations", {0.25, 0.25});
  StaticSolverOptions o = options("never", 2);
  o.steps = 4;
  o.landingTimes = {0.55, 2.0, -1.0};  // outside (0, End Time): ignored
  const std::vector<double> converged = convergedTimes(newton, o);
  const std::vector<double> expected{0.125, 0.1875, 0.25, 0.375, 0.5, 0.55, 0.75, 1.0};
  ASSERT_EQ(converged.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(converged[i], expected[i], 1e-12) << i;
}

// Load Steps/Times: the steps end on each entry when none fails, and a cut in one interval
// leaves the next interval's step whole (the fraction of its nominal step carries over).
TEST(LoadStepping, StepsEndOnEveryEntryOfTimes) {
  ScriptedNewton newton("");
  StaticSolverOptions o = options("never", 2);
  o.steps = 1;
  o.times = {0.002, 0.01, 0.0158, 0.15, 0.2, 1.0};
  const std::vector<double> converged = convergedTimes(newton, o);
  ASSERT_EQ(converged.size(), o.times.size());
  for (std::size_t i = 0; i < o.times.size(); ++i)
    EXPECT_NEAR(converged[i], o.times[i], 1e-14) << i;
  EXPECT_EQ(o.requestedSteps(), 6);
}

// The step to 0.4 (its interval 0.3 long) fails once: cut to 0.25, then 0.4; the next interval
// (0.6) is taken whole.
TEST(LoadStepping, ACutStaysInItsIntervalOfTimes) {
  ScriptedNewton newton("max-iterations", {0.4});
  StaticSolverOptions o = options("never", 1);
  o.steps = 1;
  o.times = {0.1, 0.4, 1.0};
  const std::vector<double> converged = convergedTimes(newton, o);
  const std::vector<double> expected{0.1, 0.25, 0.4, 1.0};
  ASSERT_EQ(converged.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(converged[i], expected[i], 1e-14) << i;
}

TEST(LoadStepping, TimesAreValidated) {
  const auto from = [](const Teuchos::ParameterList& loadSteps) {
    return StaticSolverOptions::from(loadSteps, *StaticSolverOptions::validNewton(),
                                     *StaticSolverOptions::validAlgorithm());
  };
  const auto loadSteps = [](const std::vector<double>& times) {
    Teuchos::ParameterList given;
    given.set("Times", Teuchos::Array<double>(times));
    validateAndSetDefaults(given, *StaticSolverOptions::validLoadSteps(), "scene.yaml");
    return given;
  };
  // End Time left out: the last entry.
  EXPECT_EQ(from(loadSteps({0.5, 2.5})).endTime, 2.5);
  EXPECT_EQ(from(loadSteps({0.5, 2.5})).times, (std::vector<double>{0.5, 2.5}));
  const auto refused = [&](const Teuchos::ParameterList& list, const std::string& words) {
    try {
      from(list);
      ADD_FAILURE() << "accepted; expected: " << words;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused(loadSteps({0.5, 0.2}), "must be finite, > 0 and increase (0.2 after 0.5)");
  refused(loadSteps({0.0, 1.0}), "must be finite, > 0 and increase (0)");
  Teuchos::ParameterList withSteps = loadSteps({0.5, 1.0});
  withSteps.set("Steps", 4);
  refused(withSteps, "Steps and Times both given");
  Teuchos::ParameterList withEnd = loadSteps({0.5, 2.0});
  withEnd.set("End Time", 1.0);  // given: it must agree
  refused(withEnd, "End Time (1) is not the last entry of Load Steps/Times (2)");
  withEnd.set("End Time", 2.0);
  EXPECT_EQ(from(withEnd).endTime, 2.0);
}

}  // namespace
}  // namespace contactlab
