// StaticSolver's start of a step (doc/algorithms.md "Predictor", "Extrapolated start"): the
// tangent predictor for moved prescribed values, the start extrapolated from the last step, the
// solid-alone first iterate. solveStep (StaticSolver.cpp) picks among them.
#include "algorithms/SolidAlonePredictor.hpp"
#include "algorithms/StaticSolver.hpp"
#include "base/Elapsed.hpp"

#include <chrono>
#include <cmath>
#include <string>

namespace contactlab {

StaticSolver::Prediction StaticSolver::predict(const Vector& u, Vector& x, StepReport& sr,
                                               RunReport& report) {
  Prediction p;
  // With contact, the undeformed state's tangent carries no contact load (at most touching
  // points at zero pressure): the predictor's linear step then moves a pressed body almost
  // rigidly into the other one (Cattaneo-Mindlin from its single touching point ends with
  // degraded-contact or max-iterations, the mortar 2D patch tests geometry-not-converged).
  // With the statuses a fixed point, the statuses frozen at the predicted state failed
  // ironing-2d's first drag step (statuses-not-converged). Elsewhere the predictor is a net win
  // (doc/algorithms.md "Predictor").
  const bool wanted = options_.predictor == "tangent" ||
                      (options_.predictor == "automatic" &&
                       (controls_ == nullptr || (options_.statusesInNewton && u.normInf() > 0)));
  if (!wanted || solver_ == nullptr) return p;
  auto increment = problem_.createVector();  // du_D: nonzero on the prescribed dofs only
  increment->update(1.0, x, -1.0, u, 0.0);
  const double size = increment->normInf();
  if (size == 0) return p;
  p.done = true;
  using clock = std::chrono::steady_clock;
  const double t = sr.time;
  auto t0 = clock::now();
  // The tangent's prescribed columns are eliminated, so K(u)_{.D} du_D is taken as the
  // derivative of R along du_D: a forward difference of two residuals, exact for a linear
  // solid up to round-off. The step h du_D is a millionth of the increment.
  constexpr double h = 1e-6;
  auto rhs = problem_.createVector();
  problem_.assemble(u, t, rhs.get(), true);
  AssemblyFailure failure = problem_.assemblyFailure();
  if (failure.code.empty()) {
    auto shifted = problem_.createVector();
    shifted->update(1.0, u, h, *increment, 0.0);
    auto shiftedResidual = problem_.createVector();
    problem_.assemble(*shifted, t, shiftedResidual.get(), false);
    failure = problem_.assemblyFailure();
    shiftedResidual->update(-1.0, *rhs, 1.0);  // R(u + h du_D) - R(u)
    rhs->update(-1.0 / h, *shiftedResidual, -1.0);
  }
  sr.seconds.assembly += secondsSince(t0);
  if (!failure.code.empty()) {
    p.failure = failure.code;
    p.message = failure.message + " (tangent predictor, at the last converged state)";
    return p;
  }
  p.residual = rhs->norm2();
  if (!std::isfinite(p.residual)) {
    p.failure = "nan-detected";
    p.message = "the tangent predictor's residual is not finite";
    return p;
  }
  t0 = clock::now();
  try {
    solver_->setMatrix(problem_.tangent(), problem_.takePatternChanged());
    auto du = problem_.createVector();
    solver_->solve(*rhs, *du);
    throwIfNumericallySingular(*problem_.tangent(), *rhs, *du);
    problem_.completeIncrement(*du);
    x.update(1.0, *du, 1.0);
  } catch (const SingularMatrixError& e) {
    p.failure = kSingularTangent;
    p.message = "tangent predictor: " + singularTangentMessage(0, e.what());
  } catch (const LinearSolverError& e) {
    p.failure = "linear-solver-failed";
    p.message = std::string("tangent predictor: ") + e.what();
  }
  sr.seconds.linearSolve += secondsSince(t0);
  ++sr.iterations;
  ++report.linearSolves;
  return p;
}

StaticSolver::ExtrapolatedStart StaticSolver::extrapolatedStart(const Vector& u, Vector& x,
                                                                double t, Vector& residual) {
  const bool wanted =
      options_.extrapolation == "linear" || (options_.extrapolation == "automatic" &&
                                             (controls_ == nullptr || statusLoopOutsideNewton()));
  if (!wanted) return {};
  problem_.assemble(x, t, &residual, false);
  if (!problem_.assemblyFailure().code.empty()) {
    extrapolation_.skipStep();
    return {};
  }
  extrapolation_.beginStep(residual);
  const double plain = residual.norm2();
  const double a = extrapolation_.factor();
  if (a == 0) return {false, plain};  // residual holds R at the plain start, x
  auto plainStart = problem_.createVector();
  plainStart->assign(x);
  extrapolation_.extrapolate(u, a, x);
  problem_.applyDirichlet(t, x);  // the prescribed values at t, not extrapolated
  problem_.updateGeometry(x, t);
  problem_.assemble(x, t, &residual, false);
  // A guess the system cannot evaluate (an element turned inside out, a contact facet without
  // its basis) is no start: the plain one is taken instead.
  if (!problem_.assemblyFailure().code.empty() || !std::isfinite(residual.norm2())) {
    x.assign(*plainStart);
    problem_.updateGeometry(x, t);
    return {};
  }
  return {true, plain};
}

bool StaticSolver::stepSolidAlone(Vector& x, double t, StepReport& sr) {
  if (!solidAlone_)
    solidAlone_ = std::make_unique<SolidAlonePredictor>(options_.predictor == "solid-alone");
  const auto t0 = std::chrono::steady_clock::now();
  const bool moved = solidAlone_->step(*controls_, x, t);
  sr.seconds.linearSolve += secondsSince(t0);
  if (moved) ++sr.iterations;
  return moved;
}

}  // namespace contactlab
