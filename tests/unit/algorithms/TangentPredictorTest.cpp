// StaticSolver's tangent predictor on a chain of three unit springs: dof 0 prescribed
// (x0 = t), dofs 1 and 2 free, dof 2 tied to the ground. Eliminated as Problem.hpp does (unit
// row and column on dof 0, its residual zeroed), the system is linear, so the predictor lands
// on the solution x1 = 2 t / 3, x2 = t / 3: Newton then has nothing left to do. Without the
// predictor Newton starts from x = (t, 0, 0). A cubic term makes the chain nonlinear: the
// predictor is then a start, and the step must still converge to R = 0.
#include "algorithms/PlainNewton.hpp"
#include "algorithms/StaticSolver.hpp"
#include "linear/Klu2Solver.hpp"

#include <Tpetra_Core.hpp>

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab {
namespace {

class SpringChain : public NonlinearSystem {
 public:
  explicit SpringChain(double cubic) : cubic_(cubic) {
    auto comm = Tpetra::getDefaultComm();
    map_ = Teuchos::rcp(new Map(3, 0, comm));
    tangent_ = Teuchos::rcp(new Matrix(map_, 3));
    for (GO r = 0; r < 3; ++r) {
      const GO cols[3] = {0, 1, 2};
      const double zeros[3] = {0, 0, 0};
      tangent_->insertGlobalValues(r, 3, zeros, cols);
    }
    tangent_->fillComplete();
  }

  Teuchos::RCP<Vector> createVector() const override { return Teuchos::rcp(new Vector(map_)); }
  void applyDirichlet(double t, Vector& x) const override { x.getDataNonConst(0)[0] = t; }
  // Springs 0-1 and 1-2 carry f = d + cubic d^3 (d the elongation), spring 2-ground f = x2.
  void assemble(const Vector& xv, double, Vector* residual, bool withTangent) override {
    ++assemblies;
    const auto x = xv.getData(0);
    const double d01 = x[1] - x[0], d12 = x[2] - x[1];
    const double f01 = d01 + cubic_ * d01 * d01 * d01, f12 = d12 + cubic_ * d12 * d12 * d12;
    const double k01 = 1 + 3 * cubic_ * d01 * d01, k12 = 1 + 3 * cubic_ * d12 * d12;
    if (residual) {
      auto r = residual->getDataNonConst(0);
      r[0] = 0.0;  // the prescribed dof's residual is its reaction, not an equation
      r[1] = f01 - f12;
      r[2] = f12 + x[2];
    }
    if (withTangent) {
      tangent_->resumeFill();
      const GO cols[3] = {0, 1, 2};
      const double rows[3][3] = {{1, 0, 0}, {0, k01 + k12, -k12}, {0, -k12, k12 + 1}};
      for (GO r = 0; r < 3; ++r)
        tangent_->replaceGlobalValues(r, 3, rows[r], cols);
      tangent_->fillComplete();
    }
  }
  const Teuchos::RCP<Matrix>& tangent() const override { return tangent_; }
  void commitState(const Vector&, double) override {}
  int assemblies = 0;

 private:
  double cubic_;
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<Matrix> tangent_;
};

// Records where each Newton solve starts, then runs the real plain Newton.
class RecordingNewton : public NewtonMethod {
 public:
  RecordingNewton(NonlinearSystem& system, LinearSolver& solver)
      : newton_(system, solver, nullptr) {}
  NewtonOutcome solve(Vector& x, const NewtonRequest& request, const Observer& observer) override {
    const auto v = x.getData(0);
    starts.push_back({v[0], v[1], v[2]});
    return newton_.solve(x, request, observer);
  }
  std::vector<std::array<double, 3>> starts;

 private:
  PlainNewton newton_;
};

struct Outcome {
  RunReport report;
  std::array<double, 3> start, solution;
};

Outcome run(double cubic, bool predictor, double endTime) {
  SpringChain chain(cubic);
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  RecordingNewton newton(chain, solver);
  StaticSolverOptions options;
  options.endTime = endTime;
  options.predictor = predictor ? "tangent" : "none";
  StaticSolver stepper(chain, nullptr, newton, options, &solver);
  auto u = chain.createVector();
  Outcome out;
  out.report = stepper.run(*u, {});
  out.start = newton.starts.at(0);
  const auto v = u->getData(0);
  out.solution = {v[0], v[1], v[2]};
  return out;
}

TEST(TangentPredictor, LandsOnTheSolutionOfALinearSystem) {
  const Outcome o = run(0.0, true, 3.0);
  ASSERT_TRUE(o.report.converged) << o.report.message;
  EXPECT_NEAR(o.start[0], 3.0, 1e-12);
  EXPECT_NEAR(o.start[1], 2.0, 1e-8);  // the forward difference is exact up to round-off
  EXPECT_NEAR(o.start[2], 1.0, 1e-8);
  EXPECT_EQ(o.report.iterations, 1);  // the predictor's solve; Newton starts converged
  EXPECT_EQ(o.report.linearSolves, 1);
}

TEST(TangentPredictor, WithoutItNewtonStartsFromThePrescribedValuesAlone) {
  const Outcome o = run(0.0, false, 3.0);
  ASSERT_TRUE(o.report.converged) << o.report.message;
  EXPECT_EQ(o.start, (std::array<double, 3>{3.0, 0.0, 0.0}));
  EXPECT_NEAR(o.solution[1], 2.0, 1e-10);
  EXPECT_EQ(o.report.iterations, 1);
}

TEST(TangentPredictor, StartsANonlinearStepThatNewtonFinishes) {
  const Outcome o = run(0.5, true, 1.0);
  ASSERT_TRUE(o.report.converged) << o.report.message;
  // The predictor used the tangent at u = 0 (unit springs): the linear solution.
  EXPECT_NEAR(o.start[1], 2.0 / 3.0, 1e-7);
  EXPECT_NEAR(o.start[2], 1.0 / 3.0, 1e-7);
  // The solution balances the springs: f01 = f12 = x2.
  const double x0 = o.solution[0], x1 = o.solution[1], x2 = o.solution[2];
  const double d01 = x1 - x0, d12 = x2 - x1;
  EXPECT_NEAR(d01 + 0.5 * std::pow(d01, 3), d12 + 0.5 * std::pow(d12, 3), 1e-9);
  EXPECT_NEAR(d12 + 0.5 * std::pow(d12, 3), -x2, 1e-9);
  EXPECT_GT(o.report.iterations, 1);
}

}  // namespace
}  // namespace contactlab
