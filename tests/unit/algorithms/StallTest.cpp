// Newton/Stall Iterations: a Newton solve whose iterates stay far above its first ||R|| (more
// than kStallFactor = 100 times it) for Stall Iterations in a row gives up instead of spending the
// rest of Max Iterations (the failing full steps of the frictional hex27 tube climb to
// 1e3-1e8 times their start and stay there). The residual histories are scripted: the system
// returns the next value of its list at each evaluation, whatever the iterate.
#include "ScalarSystem.hpp"

#include "algorithms/PlainNewton.hpp"
#include "algorithms/StaticSolver.hpp"
#include "linear/Klu2Solver.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <vector>

namespace contactlab {
namespace {

NewtonOutcome solveWithHistory(const std::vector<double>& history, int stallIterations) {
  std::size_t evaluations = 0;
  test::ScalarSystem system(
      [&](double, double) { return history[std::min(evaluations++, history.size() - 1)]; },
      [](double, double) { return 1.0; }, 1.0);
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  PlainNewton newton(system, solver, nullptr);
  NewtonRequest request;
  request.time = 1;
  request.target = 1e-10;
  request.maxIterations = 20;
  request.stallIterations = stallIterations;
  auto x = system.createVector();
  return newton.solve(*x, request, {});
}

// Start 1, then eight iterates above 100: the eighth gives up (8 linear solves).
const std::vector<double> kFarAway{1, 500, 300, 2e4, 150, 120, 110, 105, 101, 101};

TEST(StalledNewton, EightIteratesFarAboveTheStartGiveUp) {
  const NewtonOutcome out = solveWithHistory(kFarAway, 8);
  EXPECT_EQ(out.failure, "diverged");
  EXPECT_EQ(out.iterations, 8);
  EXPECT_NE(out.message.find("Newton stalled: 8 iterations with ||R|| > 1.000e+02"),
            std::string::npos)
      << out.message;
}

TEST(StalledNewton, OffTheSolveSpendsMaxIterations) {
  const NewtonOutcome out = solveWithHistory(kFarAway, 0);
  EXPECT_EQ(out.failure, "max-iterations");
  EXPECT_EQ(out.iterations, 20);
}

TEST(StalledNewton, AnIterateBackWithin100TimesTheStartStartsTheCountAgain) {
  // Seven far iterates, one at 50 (within 100 x 1), seven far again, then converged: as a
  // converging contact solve may (the pad's fixed point at nu = 0.499: 9 in a row at 10-16 x).
  const NewtonOutcome out = solveWithHistory(
      {1, 500, 500, 500, 500, 500, 500, 500, 50, 500, 500, 500, 500, 500, 500, 500, 1e-3, 1e-12},
      8);
  EXPECT_TRUE(out.failure.empty()) << out.message;
  EXPECT_EQ(out.iterations, 17);
}

TEST(StalledNewton, TheOptionIsValidatedAndOnByDefault) {
  Teuchos::ParameterList newton = *StaticSolverOptions::validNewton();
  const auto from = [&] {
    return StaticSolverOptions::from(*StaticSolverOptions::validLoadSteps(), newton,
                                     *StaticSolverOptions::validAlgorithm());
  };
  EXPECT_EQ(from().stallIterations, 8);
  newton.set("Stall Iterations", -1);
  EXPECT_THROW(from(), std::invalid_argument);
}

}  // namespace
}  // namespace contactlab
