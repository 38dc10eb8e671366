// A Newton observer that changes the law at an iterate (the cycling treatment forcing a status
// or scaling coefficients) returns true, and the Newton method evaluates the residual and the
// tangent there again: its step solves the law the next iterate is judged by, and its status
// tests read the new residual. Before, PlainNewton stepped with the untreated law (on the hex8
// frictional tube the forced stick of slip reversals put the iterate 1000 x off equilibrium and
// the step diverged) and NOX's next step read the untreated residual with the treated tangent.
// The scalar law R(x) = 2 (x - root), whose root the observer moves from 1 to 3.
#include "ScalarSystem.hpp"

#include "algorithms/NoxNewton.hpp"
#include "algorithms/PlainNewton.hpp"
#include "linear/Klu2Solver.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <utility>
#include <vector>

namespace contactlab {
namespace {

struct MovingRoot {
  double root = 1.0;
  test::ScalarSystem system{[this](double x, double) { return 2 * (x - root); },
                            [](double, double) { return 2.0; }, 1.0};
};

NewtonRequest request() {
  return test::newtonRequest(1e-12, 10);
}

TEST(ObserverChangesLaw, PlainNewtonStepsWithTheChangedLaw) {
  MovingRoot law;
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  PlainNewton newton(law.system, solver, nullptr);
  auto x = law.system.createVector();
  const NewtonOutcome out = newton.solve(*x, request(),
                                         {[&](int iteration) {
                                            if (iteration != 0) return false;
                                            law.root = 3.0;
                                            return true;
                                          },
                                          {}});
  ASSERT_TRUE(out.failure.empty()) << out.message;
  EXPECT_DOUBLE_EQ(x->getData(0)[0], 3.0);
  // One step from the changed law's residual; with the old one's, a step to 1 and one more.
  EXPECT_EQ(out.iterations, 1);
}

TEST(ObserverChangesLaw, AnObserverThatChangesNothingCostsNoEvaluation) {
  int evaluations = 0;
  test::ScalarSystem counted(
      [&](double x, double) {
        ++evaluations;
        return 2 * (x - 1.0);
      },
      [](double, double) { return 2.0; }, 1.0);
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  PlainNewton newton(counted, solver, nullptr);
  auto x = counted.createVector();
  const NewtonOutcome out = newton.solve(*x, request(), {[](int) { return false; }, {}});
  ASSERT_TRUE(out.failure.empty()) << out.message;
  EXPECT_EQ(out.iterations, 1);
  EXPECT_EQ(evaluations, 2);  // the start and the solution
}

// NOX observes an iterate after its status tests; a law changed there is read by the next
// iteration: its direction and line search. On a cubic law whose root moves from 1 to 3 at the
// first iterate (x = 0.5), NOX's full steps then take PlainNewton's iterates; with the old
// law's residual at 0.5 (stale, 34 times smaller than the new law's) its next step went back
// towards 1 and the solve took one iteration more.
TEST(ObserverChangesLaw, NoxStepsWithTheChangedLaw) {
  const auto solveWith = [](NewtonMethod& newton, test::ScalarSystem& system, double& root) {
    auto x = system.createVector();
    const NewtonOutcome out = newton.solve(*x, request(),
                                           {[&](int iteration) {
                                              if (iteration != 1) return false;
                                              root = 3.0;
                                              return true;
                                            },
                                            {}});
    EXPECT_TRUE(out.failure.empty()) << out.message;
    EXPECT_NEAR(x->getData(0)[0], 3.0, 1e-12);
    return out.iterations;
  };
  double root = 1.0;
  test::ScalarSystem cubic([&](double x, double) { return std::pow(x - root, 3) + (x - root); },
                           [&](double x, double) { return 3 * std::pow(x - root, 2) + 1; }, 1.0);
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  PlainNewton plain(cubic, solver, nullptr);
  const int plainIterations = solveWith(plain, cubic, root);
  root = 1.0;
  NoxNewton nox(cubic, solver, nullptr, "Full Step");
  EXPECT_EQ(solveWith(nox, cubic, root), plainIterations);
}

// The residual reported at a treated iterate (progress lines, the step's residual) is the one
// the method goes on with: the changed law's. Before, the progress line of a treated iterate
// showed the residual of the law before the treatment. The cubic law above at x = 0.5: |R| =
// 0.625 with the root at 1, 18.125 with the root moved to 3.
TEST(ObserverChangesLaw, TheReportedResidualIsTheChangedLaws) {
  double root = 1.0;
  test::ScalarSystem cubic([&](double x, double) { return std::pow(x - root, 3) + (x - root); },
                           [&](double x, double) { return 3 * std::pow(x - root, 2) + 1; }, 1.0);
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  PlainNewton plain(cubic, solver, nullptr);
  NoxNewton nox(cubic, solver, nullptr, "Full Step");
  for (NewtonMethod* newton :
       {static_cast<NewtonMethod*>(&plain), static_cast<NewtonMethod*>(&nox)}) {
    root = 1.0;
    std::vector<std::pair<int, double>> reported;
    auto x = cubic.createVector();
    const NewtonOutcome out = newton->solve(
        *x, request(),
        {[&](int iteration) {
           if (iteration != 1) return false;
           root = 3.0;
           return true;
         },
         [&](int iteration, double residual) { reported.emplace_back(iteration, residual); }});
    ASSERT_TRUE(out.failure.empty()) << out.message;
    const auto first =
        std::find_if(reported.begin(), reported.end(), [](const auto& r) { return r.first == 1; });
    ASSERT_NE(first, reported.end());
    EXPECT_NEAR(first->second, 18.125, 1e-12);
  }
}

}  // namespace
}  // namespace contactlab
