// NoxNewton reports the seconds of its model evaluations and of its factorizations and solves,
// as PlainNewton does: steps.csv's assembly_s and linear_solve_s of a step NOX solved (Driver:
// nox, or the line-search retry of a failed step) come from them. They were left at 0, and
// assembly_s (assembly minus the contact terms) came out negative.
#include "ScalarSystem.hpp"

#include "algorithms/NoxNewton.hpp"
#include "linear/Klu2Solver.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

TEST(NoxPhaseSeconds, ASolveReportsItsAssemblyAndLinearSolveSeconds) {
  test::ScalarSystem system([](double x, double) { return std::atan(x - 0.3); },
                            [](double x, double) { return 1 / (1 + (x - 0.3) * (x - 0.3)); }, 1.0);
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  for (const char* lineSearch : {"Full Step", "Backtrack"}) {
    NoxNewton newton(system, solver, nullptr, lineSearch);
    NewtonRequest request;
    request.time = 1;
    request.target = 1e-12;
    auto x = system.createVector();
    const NewtonOutcome out = newton.solve(*x, request, {});
    ASSERT_TRUE(out.failure.empty()) << lineSearch << ": " << out.message;
    EXPECT_GT(out.iterations, 0) << lineSearch;
    // Every iteration evaluated the model and factorized: a positive time each (the clock
    // counts nanoseconds; an evaluation fills a matrix).
    EXPECT_GT(out.assemblySeconds, 0.0) << lineSearch;
    EXPECT_GT(out.linearSolveSeconds, 0.0) << lineSearch;
  }
}

}  // namespace
}  // namespace contactlab
