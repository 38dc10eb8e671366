#pragma once
// A nonlinear system of one unknown, R(x, t) and dR/dx given as functions: the textbook cases
// of Newton's failures (a tangent that flattens away from the root, a 2-cycle) for the tests of
// the static solver's remedies.
#include "algorithms/NewtonMethod.hpp"
#include "algorithms/PlainNewton.hpp"
#include "core/problem/NonlinearSystem.hpp"
#include "linear/Klu2Solver.hpp"

#include <Tpetra_Core.hpp>

#include <algorithm>
#include <functional>
#include <utility>
#include <vector>

namespace contactlab::test {

class ScalarSystem : public NonlinearSystem {
 public:
  using Function = std::function<double(double x, double t)>;
  ScalarSystem(Function residual, Function derivative, double size)
      : residual_(std::move(residual)), derivative_(std::move(derivative)), size_(size) {
    map_ = Teuchos::rcp(new Map(1, 0, Tpetra::getDefaultComm()));
    tangent_ = Teuchos::rcp(new Matrix(map_, 1));
    const GO col = 0;
    const double zero = 0;
    tangent_->insertGlobalValues(0, 1, &zero, &col);
    tangent_->fillComplete();
  }
  Teuchos::RCP<Vector> createVector() const override { return Teuchos::rcp(new Vector(map_)); }
  void applyDirichlet(double, Vector&) const override {}
  void assemble(const Vector& xv, double t, Vector* residual, bool withTangent) override {
    const double x = xv.getData(0)[0];
    if (residual) residual->getDataNonConst(0)[0] = residual_(x, t);
    if (withTangent) {
      tangent_->resumeFill();
      const GO col = 0;
      const double k = derivative_(x, t);
      tangent_->replaceGlobalValues(0, 1, &k, &col);
      tangent_->fillComplete();
    }
  }
  const Teuchos::RCP<Matrix>& tangent() const override { return tangent_; }
  void commitState(const Vector&, double) override {}
  double modelSize() const override { return size_; }

 private:
  Function residual_, derivative_;
  double size_;
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<Matrix> tangent_;
};

// A Newton solve's request at t = 1 (the scalar laws do not depend on t).
inline NewtonRequest newtonRequest(double target, int maxIterations) {
  NewtonRequest r;
  r.time = 1;
  r.target = target;
  r.maxIterations = maxIterations;
  return r;
}

// A PlainNewton solve from x = 0 of a system whose ||R|| follows a script: the next value at
// each evaluation, whatever the iterate, and the last one from then on (dR/dx = 1).
inline NewtonOutcome solveScripted(const std::vector<double>& history,
                                   const NewtonRequest& request) {
  std::size_t evaluations = 0;
  ScalarSystem system(
      [&](double, double) { return history[std::min(evaluations++, history.size() - 1)]; },
      [](double, double) { return 1.0; }, 1.0);
  Klu2Solver solver({}, Tpetra::getDefaultComm());
  PlainNewton newton(system, solver, nullptr);
  auto x = system.createVector();
  return newton.solve(*x, request, {});
}

}  // namespace contactlab::test
