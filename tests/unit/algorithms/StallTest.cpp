// Newton/Stall Iterations: a Newton solve whose iterates stay far above its first ||R|| (more
// than kStallFactor = 100 times it) for Stall Iterations in a row, or repeat a two-iterate cycle,
// gives up instead of spending the rest of Max Iterations (the failing full steps of the frictional
// hex27 tube climb to 1e3-1e8 times their start and stay there). The residual histories are
// scripted: the system returns the next value of its list at each evaluation, whatever the iterate.
#include "ScalarSystem.hpp"

#include "algorithms/StaticSolver.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace contactlab {
namespace {

NewtonOutcome solveWithHistory(const std::vector<double>& history, int stallIterations) {
  NewtonRequest request = test::newtonRequest(1e-10, 20);
  request.stallIterations = stallIterations;
  return test::solveScripted(history, request);
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
      {1, 500, 510, 520, 530, 540, 550, 560, 50, 500, 510, 520, 530, 540, 550, 560, 1e-3, 1e-12},
      8);
  EXPECT_TRUE(out.failure.empty()) << out.message;
  EXPECT_EQ(out.iterations, 17);
}

// The frictional hex27 tube's unloading step (tube-expansion-3d, mu = 0.3, t = 2): after the
// cycling treatment had acted, its full steps alternated between these two residuals, drifting
// in the 9th digit, until Max Iterations.
const std::vector<double> kTubeCycle{
    50.76286663830, 12.28081365189, 17.06812283330, 18.43113849811, 24.16731407271, 29.67260031818,
    42.46512855399, 44.45967156129, 53.29826543472, 50.35167732526, 54.10145205070, 50.35167718330,
    54.10145154601, 50.35167718591, 54.10145132861, 50.35167718809, 54.10145123197, 50.35167718915};

TEST(StalledNewton, ResidualsThatRepeatATwoIterateCycleGiveUp) {
  EXPECT_FALSE(newtonCycles({1, 2, 1, 2}));
  EXPECT_TRUE(newtonCycles({9, 1, 2, 1, 2, 1}));
  EXPECT_TRUE(newtonCycles({3, 3, 3, 3, 3}));  // no progress at all
  EXPECT_FALSE(newtonCycles({1, 2, 1, 2, 1.01}));
  EXPECT_FALSE(newtonCycles({5, 4, 3, 2, 1}));
  const NewtonOutcome out = solveWithHistory(kTubeCycle, 8);
  EXPECT_EQ(out.failure, "diverged");
  EXPECT_EQ(out.iterations, 13);  // iterates 9-13 alternate: given up at the 13th
  EXPECT_NE(out.message.find("Newton cycles: ||R|| alternates 5.410e+01 and 5.035e+01"),
            std::string::npos)
      << out.message;
  EXPECT_EQ(solveWithHistory(kTubeCycle, 0).failure, "max-iterations");  // off with the stall test
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
