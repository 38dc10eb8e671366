#include "algorithms/StaticSolver.hpp"

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>

namespace contactlab {
namespace {

std::string sci(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3e", v);
  return buffer;
}

double seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Teuchos::RCP<const Teuchos::ParameterList> StaticSolverOptions::validLoadSteps() {
  auto p = Teuchos::rcp(new Teuchos::ParameterList("Load Steps"));
  p->set("Steps", 1, "Number of equal load steps from t = 0 to End Time (>= 1)");
  p->set("End Time", 1.0, "Pseudo-time at the end of the load (> 0); ramps reach 1 there");
  return p;
}

Teuchos::RCP<const Teuchos::ParameterList> StaticSolverOptions::validNewton() {
  auto p = Teuchos::rcp(new Teuchos::ParameterList("Newton"));
  p->set("Max Iterations", 20, "Newton iterations allowed per load step (>= 1)");
  p->set("Relative Tolerance", 1e-8,
         "Converged when ||R|| <= Relative Tolerance * ||R at the step's first iterate||");
  p->set("Absolute Tolerance", 1e-12, "... or when ||R|| <= Absolute Tolerance");
  p->set("Geometry Tolerance", 1e-6,
         "Contact: the geometric fixed point has converged when the residual at the updated "
         "geometry is <= Geometry Tolerance * ||R at the step's first iterate||");
  p->set("Driver", "plain",
         "'plain': contactlab's Newton loop; 'nox': each Newton solve run by NOX's line-search "
         "based solver (Line Search below)",
         Teuchos::rcp(new Teuchos::StringValidator(Teuchos::tuple<std::string>("plain", "nox"))));
  p->set("Line Search", "Full Step", "NOX line search (Driver: nox)",
         Teuchos::rcp(new Teuchos::StringValidator(Teuchos::tuple<std::string>(
             "Full Step", "Backtrack", "Polynomial", "More'-Thuente"))));
  p->set("Max Geometry Iterations", 10,
         "Contact: geometry updates (pairing, normals) allowed per step after Newton "
         "converged with the geometry frozen (>= 0)");
  return p;
}

StaticSolverOptions StaticSolverOptions::from(const Teuchos::ParameterList& loadSteps,
                                              const Teuchos::ParameterList& newton) {
  StaticSolverOptions o;
  o.steps = loadSteps.get<int>("Steps");
  o.endTime = loadSteps.get<double>("End Time");
  o.maxIterations = newton.get<int>("Max Iterations");
  o.relativeTolerance = newton.get<double>("Relative Tolerance");
  o.absoluteTolerance = newton.get<double>("Absolute Tolerance");
  o.maxGeometryIterations = newton.get<int>("Max Geometry Iterations");
  o.geometryTolerance = newton.get<double>("Geometry Tolerance");
  o.driver = newton.get<std::string>("Driver");
  o.lineSearch = newton.get<std::string>("Line Search");
  if (o.driver == "plain" && o.lineSearch != "Full Step")
    throw std::invalid_argument("Newton/Line Search '" + o.lineSearch +
                                "' needs Newton/Driver: nox (the plain Newton takes full steps)");
  if (o.steps < 1) throw std::invalid_argument("Load Steps/Steps must be >= 1");
  if (!(o.endTime > 0)) throw std::invalid_argument("Load Steps/End Time must be > 0");
  if (o.maxIterations < 1) throw std::invalid_argument("Newton/Max Iterations must be >= 1");
  if (o.maxGeometryIterations < 0)
    throw std::invalid_argument("Newton/Max Geometry Iterations must be >= 0");
  if (!(o.relativeTolerance >= 0) || !(o.absoluteTolerance >= 0) || !(o.geometryTolerance >= 0))
    throw std::invalid_argument("Newton tolerances must be >= 0");
  return o;
}

StaticSolver::StaticSolver(NonlinearSystem& problem, LinearSolver& solver,
                           StaticSolverOptions options)
    : problem_(problem), solver_(solver), options_(options) {}

RunReport StaticSolver::run(Vector& u, const StepCallback& onStep,
                            const IterationCallback& onIteration) {
  using clock = std::chrono::steady_clock;
  RunReport report;
  auto residual = problem_.createVector();
  auto increment = problem_.createVector();
  auto trial = problem_.createVector();
  bool firstFactorization = true;

  for (int step = 1; step <= options_.steps; ++step) {
    StepReport sr;
    sr.step = step;
    sr.time = options_.endTime * step / options_.steps;
    trial->assign(u);
    problem_.applyDirichlet(sr.time, *trial);
    problem_.updateGeometry(*trial, sr.time);
    double reference = 0;
    bool converged = false, geometryFresh = false;
    for (int it = 0;; ++it) {
      auto t0 = clock::now();
      problem_.assemble(*trial, sr.time, residual.get(), true);
      sr.seconds.assembly += seconds(t0);
      const double norm = residual->norm2();
      if (it == 0) reference = norm;
      sr.residual = norm;
      if (onIteration) onIteration(step, options_.steps, it, norm);
      if (!std::isfinite(norm)) {
        report.failure = "nan-detected";
        report.message = "the residual is not finite at step " + std::to_string(step) +
                         ", iteration " + std::to_string(it);
        break;
      }
      // Just after a geometry update the residual only has to be within the geometry
      // tolerance: the frozen-geometry Newton converged, and the update moved it by less.
      if (geometryFresh &&
          norm <= std::max(options_.absoluteTolerance, options_.geometryTolerance * reference)) {
        converged = true;
        break;
      }
      if (norm <= std::max(options_.absoluteTolerance, options_.relativeTolerance * reference)) {
        // Converged at a geometry frozen at this very iterate: the fixed point has converged
        // too (the update changed the residual by less than the tolerance).
        if (geometryFresh || !problem_.updateGeometry(*trial, sr.time)) {
          converged = true;
          break;
        }
        if (sr.geometryIterations == options_.maxGeometryIterations) {
          report.failure = "geometry-not-converged";
          report.message = "the contact geometry still moved after " +
                           std::to_string(sr.geometryIterations) + " updates at step " +
                           std::to_string(step) + " (Newton/Max Geometry Iterations)";
          break;
        }
        ++sr.geometryIterations;
        geometryFresh = true;
        continue;  // the residual at the new geometry is assembled at the top
      }
      if (it > 0 && norm > 1e10 * std::max(reference, options_.absoluteTolerance)) {
        report.failure = "diverged";
        report.message =
            "Newton diverged at step " + std::to_string(step) + ": ||R|| grew to " + sci(norm);
        break;
      }
      if (sr.iterations == options_.maxIterations) {
        report.failure = "max-iterations";
        report.message =
            "Newton did not converge in " + std::to_string(it) + " iterations at step " +
            std::to_string(step) + " (||R|| = " + sci(norm) + ", target " +
            sci(std::max(options_.absoluteTolerance, options_.relativeTolerance * reference)) + ")";
        break;
      }
      t0 = clock::now();
      try {
        const bool patternChanged = problem_.takePatternChanged();
        solver_.setMatrix(problem_.tangent(), firstFactorization || patternChanged);
        firstFactorization = false;
        residual->scale(-1.0);
        increment->putScalar(0.0);
        solver_.solve(*residual, *increment);
      } catch (const LinearSolverError& e) {
        sr.seconds.linearSolve += seconds(t0);
        report.failure = "linear-solver-failed";
        report.message = std::string(e.what()) + " (step " + std::to_string(step) + ")";
        break;
      }
      sr.seconds.linearSolve += seconds(t0);
      ++report.linearSolves;
      ++sr.iterations;
      geometryFresh = false;
      trial->update(1.0, *increment, 1.0);
    }
    report.iterations += sr.iterations;
    report.geometryIterations += sr.geometryIterations;
    report.seconds.assembly += sr.seconds.assembly;
    report.seconds.linearSolve += sr.seconds.linearSolve;
    if (!converged) return report;
    u.assign(*trial);
    problem_.commitState(u, sr.time);
    ++report.steps;
    auto t0 = clock::now();
    if (onStep) onStep(sr, u);
    report.seconds.output += seconds(t0);
  }
  report.converged = true;
  return report;
}

}  // namespace contactlab
