#include "algorithms/PlainNewton.hpp"

#include "base/Elapsed.hpp"
#include "base/NumberText.hpp"
#include "linear/ResidualRoundoff.hpp"

#include <algorithm>
#include <cmath>

namespace contactlab {

bool contactSettled(const ContactControls* controls, double target, int iteration) {
  if (controls == nullptr) return true;
  return (iteration == 0 || controls->statusChanges() == 0) &&
         controls->constraintResidual() <= target;
}

bool newtonConverged(double norm, const NewtonRequest& request, const ContactControls* controls,
                     int iteration) {
  return norm <= request.target && contactSettled(controls, request.target, iteration);
}

bool newtonCycles(const std::vector<double>& norms) {
  const std::size_t n = norms.size();
  if (n < 5) return false;
  const auto same = [&](std::size_t a, std::size_t b) {
    return std::abs(norms[a] - norms[b]) <= 1e-6 * std::max(norms[a], norms[b]);
  };
  return same(n - 1, n - 3) && same(n - 3, n - 5) && same(n - 2, n - 4);
}

std::string singularTangentMessage(int iteration, const std::string& detail) {
  return "the tangent is singular at iteration " + std::to_string(iteration) + " (" + detail + ")";
}

std::string singularTangentRemedy() {
  return ": a body is not held in some direction (before contact under load control, or held "
         "only by friction), or an iterate took a perfectly plastic body to its limit load; "
         "remedies: Algorithm/Regularization: slow-dynamics (materials need a density), "
         "Contact/<zone>/Initial Contact: all, a support or Springs; past a limit load, shorter "
         "steps (Load Steps/Steps or Max Cuts)";
}

NewtonOutcome PlainNewton::solve(Vector& x, const NewtonRequest& request,
                                 const Observer& observer) {
  NewtonOutcome out;
  auto residual = system_.createVector();
  auto increment = system_.createVector();
  double start = 0;
  // Consecutive iterates with ||R|| > kStallFactor x the start's. Relative to the start alone:
  // a solve that iterates started above its target (one at or below it converges at once).
  int farIterates = 0;
  std::vector<double> norms;            // this solve's ||R|| per iterate
  NewtonRequest withForcing = request;  // the target raised by the forcing once ||R_0|| is known
  for (int it = 0;; ++it) {
    const auto evaluate = [&] {
      PhaseTimer timer(&out.assemblySeconds);
      if (request.geometryInNewton && it > 0) system_.updateGeometry(x, request.time);
      system_.assemble(x, request.time, residual.get(), true);
      return residual->norm2();
    };
    double norm = evaluate();
    // An update that lands where the system cannot be evaluated (an element inverted, a mortar
    // facet so distorted that its dual basis does not exist: a NaN residual) is halved until
    // it can, as PETSc's SNES does after a function domain error, rather than failing the
    // attempt: the seed-size tube under generalized Newton lost its step to t = 0.22 down to
    // the smallest cut so (doc/algorithms.md "Unevaluable iterates").
    for (int halving = 0; it > 0 && !std::isfinite(norm) && halving < kUnevaluableHalvings;
         ++halving) {
      increment->scale(0.5);
      x.update(-1.0, *increment, 1.0);
      ++out.unevaluableHalvings;
      norm = evaluate();
    }
    if (std::isfinite(norm) && observer.treat && observer.treat(it)) {
      // The observer changed the law at x (a cycling treatment): the step solves the new one.
      PhaseTimer timer(&out.assemblySeconds);
      system_.assemble(x, request.time, residual.get(), true);
      norm = residual->norm2();
    }
    if (std::isfinite(norm) && observer.report) observer.report(it, norm);
    out.residual = norm;
    if (it == 0) {
      start = norm;
      withForcing.target = std::max(request.target, request.forcing * start);
    }
    norms.push_back(norm);
    farIterates = norm > kStallFactor * start ? farIterates + 1 : 0;
    if (!std::isfinite(norm)) {
      out.failure = "nan-detected";
      out.message = "the residual is not finite at iteration " + std::to_string(it);
      return out;
    }
    if (newtonConverged(norm, withForcing, controls_, it)) return out;
    // A residual at the round-off of its own evaluation is as converged as it can be computed,
    // and more iterations only shuffle that round-off (a body a frozen-open fixed point threw
    // 7e5 times its size stalled there at 4e-8 of its start, above the 1e-8 asked, until the
    // cycle detector failed the step). Where the caller allows it: such an iterate may be a
    // state no one wants (a perfectly plastic tube past its limit load, 100 times its size).
    if (request.roundoffStop && norm > withForcing.target) {
      NewtonRequest atFloor = withForcing;
      atFloor.target = residualRoundoff(*system_.tangent(), x);
      if (newtonConverged(norm, atFloor, controls_, it)) {
        ++out.roundoffStops;
        return out;
      }
    }
    if (it > 0 && norm > 1e10 * std::max(start, request.target)) {
      out.failure = "diverged";
      out.message = "Newton diverged: ||R|| grew to " + scientificText(norm);
      return out;
    }
    if (request.stallIterations > 0 && farIterates >= request.stallIterations) {
      out.failure = "diverged";
      out.message = "Newton stalled: " + std::to_string(farIterates) + " iterations with ||R|| > " +
                    scientificText(kStallFactor * start) + " (" + scientificText(kStallFactor) +
                    " x its start; now " + scientificText(norm) + ")";
      return out;
    }
    if (request.stallIterations > 0 && newtonCycles(norms)) {
      out.failure = "diverged";
      out.message = "Newton cycles: ||R|| alternates " + scientificText(norms[norms.size() - 2]) +
                    " and " + scientificText(norm) + " (the same two iterates)";
      return out;
    }
    if (out.iterations == request.maxIterations) {
      out.failure = "max-iterations";
      out.message = "Newton did not converge in " + std::to_string(out.iterations) +
                    " iterations (||R|| = " + scientificText(norm) + ", target " +
                    scientificText(withForcing.target);
      if (controls_ != nullptr && norm <= withForcing.target)
        out.message += "; the contact equations' residual as forces " +
                       scientificText(controls_->constraintResidual());
      out.message += ")";
      return out;
    }
    try {
      PhaseTimer timer(&out.linearSolveSeconds);  // also counts a failed factorization
      // The solver analyses on its first matrix by itself.
      solver_.setMatrix(system_.tangent(), system_.takePatternChanged());
      residual->scale(-1.0);
      increment->putScalar(0.0);
      solver_.solve(*residual, *increment);
      throwIfNumericallySingular(*system_.tangent(), *residual, *increment);
      system_.completeIncrement(*increment);
    } catch (const SingularMatrixError& e) {
      out.failure = kSingularTangent;
      out.message = singularTangentMessage(it, e.what());
      return out;
    } catch (const LinearSolverError& e) {
      out.failure = "linear-solver-failed";
      out.message = e.what();
      return out;
    }
    ++out.iterations;
    // A near-singular tangent (a body past its limit load, or free, until it meets contact)
    // gives an update orders of magnitude too long; scaled down, Newton walks along it.
    const double largest = system_.largestDisplacement(*increment);
    out.longestUpdate = std::max(out.longestUpdate, largest);
    if (request.maxUpdate > 0 && largest > request.maxUpdate) {
      increment->scale(request.maxUpdate / largest);
      ++out.limitedUpdates;
    }
    x.update(1.0, *increment, 1.0);
  }
}

}  // namespace contactlab
