#include "algorithms/StaticSolver.hpp"

#include "algorithms/AlgorithmPresets.hpp"
#include "algorithms/SolidAlonePredictor.hpp"
#include "base/Elapsed.hpp"
#include "core/io/Interruption.hpp"
#include "core/io/ParameterValidation.hpp"

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <utility>

namespace contactlab {
namespace {

// Thrown from the Newton observer when a signal asked the run to stop (every rank at once).
struct Interrupted {
  int signal;
};

std::string sci(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3e", v);
  return buffer;
}

Teuchos::RCP<Teuchos::StringValidator> choices(std::initializer_list<std::string> names) {
  return Teuchos::rcp(new Teuchos::StringValidator(Teuchos::Array<std::string>(names)));
}

Teuchos::RCP<Teuchos::StringValidator> presetChoices() {
  Teuchos::Array<std::string> names;
  for (const AlgorithmPreset& preset : algorithmPresets())
    names.push_back(preset.name);
  return Teuchos::rcp(new Teuchos::StringValidator(names));
}

}  // namespace

Teuchos::RCP<const Teuchos::ParameterList> StaticSolverOptions::validLoadSteps() {
  auto p = Teuchos::rcp(new Teuchos::ParameterList("Load Steps"));
  p->set("Steps", 1, "Number of equal load steps from t = 0 to End Time (>= 1)");
  p->set("End Time", 1.0, "Pseudo-time at the end of the load (> 0); ramps reach 1 there");
  p->set("Max Cuts", 0,
         "A step that fails is cut in two and retried, up to this many times in a row (>= 0; "
         "0: a failed step ends the run). After a step converges without a cut the step "
         "doubles again, up to End Time / Steps. No step is cut below End Time / Steps / "
         "2^Max Cuts: a run whose every step needs a cut ends there (step-too-small). Cut or "
         "not, a step ends on every multiple of End Time / Steps, kink of a load function "
         "(a ramp's start and stop, a table's times) and Output/Contact Times entry it would "
         "pass");
  return p;
}

Teuchos::RCP<const Teuchos::ParameterList> StaticSolverOptions::validNewton() {
  auto p = Teuchos::rcp(new Teuchos::ParameterList("Newton"));
  p->set("Max Iterations", 20,
         "Newton iterations allowed per Newton solve (>= 1); a step runs "
         "one solve per fixed-point iteration");
  p->set("Relative Tolerance", 1e-8,
         "Converged when ||R|| <= Relative Tolerance * ||R at the step's first iterate|| and no "
         "contact status changed at the last iterate");
  p->set("Absolute Tolerance", 1e-12, "... or when ||R|| <= Absolute Tolerance");
  p->set("Geometry Tolerance", 1e-6,
         "Contact: the geometric fixed point has converged when the residual at the updated "
         "geometry is <= Geometry Tolerance * ||R at the step's first iterate||");
  p->set("Driver", "plain",
         "'plain': contactlab's Newton loop (full steps); 'nox': each Newton solve run by NOX's "
         "line-search based solver (Line Search below)",
         choices({"plain", "nox"}));
  p->set("Line Search", "Full Step", "NOX line search (Driver: nox)",
         choices({"Full Step", "Backtrack", "Polynomial", "More'-Thuente"}));
  p->set("Line Search Retry", "every-failure",
         "A load step whose Newton failed is solved again from the step's start by NOX's "
         "line-search based solver with the Backtrack line search (the Newton step halved until "
         "||R|| decreases) before it is cut ('every-failure'), only when it cannot be cut any "
         "more (Max Cuts or the smallest step) before the run fails ('last-resort'), or not "
         "('never'). Full steps stay the first try: a contact Newton often converges through "
         "iterates whose ||R|| grows, and backtracking every step costs more iterations on most "
         "scenes (doc/algorithms.md \"Line search retry\"). Not with Driver: nox and a line "
         "search already",
         choices({"every-failure", "last-resort", "never"}));
  p->set("Line Search Retry Max Iterations", 0,
         "Newton iterations the line-search retry may take per Newton solve; 0: twice Max "
         "Iterations. Its halved steps take more iterations than full steps, and the cut it "
         "saves costs the whole step again: with Max Iterations the hex8 tube's retries "
         "stopped at 2e-4 from converging and cut (doc/algorithms.md \"Line search retry\")");
  p->set("Max Update", 0.05,
         "A step whose full Newton steps failed through an update that moved a node by more "
         "than this fraction of the model's size (twice the largest distance of a node from the "
         "nodes' centroid: a box's diagonal) is solved again from its start with every longer "
         "update scaled down to it (multipliers too: the direction is kept), after the "
         "line-search retry and before a cut. So long an update comes from a tangent that is "
         "nearly singular: a body past its limit load (perfect plasticity), or held only by "
         "contact under load control (doc/algorithms.md \"Update limit\"). A step that "
         "converges with full steps is never limited. >= 0; 0: no such retry. Driver: plain");
  p->set("Stall Iterations", 8,
         "A Newton solve whose last Stall Iterations iterates all had ||R|| above 100 times its "
         "first one gives up ('diverged') and goes to the retries or the cut instead of "
         "spending the rest of Max Iterations: a frictional step whose full steps fail climbs to "
         "||R|| 1e3-1e8 times its start and stays there (doc/algorithms.md \"Stalled "
         "Newton\"); so does one whose last five ||R|| alternate a, b, a, b, a to 1e-6 (a "
         "cycle the cycling treatment did not break). >= 0; 0: never (neither test). Not in the "
         "update-limit retry (its short updates may take "
         "long to descend). Driver: plain");
  p->set("Predictor", "automatic",
         "Start of a step whose prescribed displacements move: 'tangent' solves K(u_n) du = "
         "-R(u_n, t) - K(u_n) du_D, which spreads the prescribed increment du_D through the "
         "body with the last converged tangent (code_aster's PREDICTION='TANGENTE'; one linear "
         "solve, counted as an iteration); 'none' starts Newton from u_n with the new prescribed "
         "values, so the whole increment first strains the elements along the constrained "
         "boundary (plastic or inverted elements there can make Newton fail); 'automatic': "
         "tangent, except for a model with contact at the undeformed state u_n = 0 (there the "
         "last tangent carries no contact load, and the predictor moves a pressed body into "
         "its obstacle) or with the contact statuses a fixed point (Algorithm/Method: "
         "fixed-point); at a contact model's step from u_n = 0 with the statuses in Newton, "
         "'solid-alone' from 20 000 displacement dofs. 'solid-alone': a step that starts with "
         "no contact point carrying a force (all open, or touching at zero pressure) takes the "
         "solid's own step without contact, solved by CG with MueLu to 1e-3, as its first "
         "iterate, where Newton would factorize a matrix it discards at the next iteration "
         "(counted as an iteration; the geometry stays paired at the step's start). Measured "
         "in doc/algorithms.md. Steps driven by loads alone start from u_n with 'tangent'",
         choices({"automatic", "tangent", "solid-alone", "none"}));
  p->set("Extrapolation", "automatic",
         "Start of a step after the first converged one: 'linear' moves the last converged "
         "state u_n by the last step's increment (multipliers too) scaled by this step's load "
         "increment projected on the last one's, a = r.r_n / r_n.r_n in [0, 2], r = R(u_n, "
         "t_{n+1}) the plain start's residual (Abaqus' default extrapolation, code_aster's "
         "PREDICTION='EXTRAPOLE'); a load held or turned back (a = 0) starts from u_n, and the "
         "step's tolerance stays relative to ||r||. Used in place of the Predictor. 'none': "
         "u_n (with the Predictor). 'automatic': linear for a model without contact and with "
         "the contact statuses a fixed point (Algorithm/Method: fixed-point, whose statuses "
         "and thresholds are frozen at the step's start), none where the statuses are in "
         "Newton (there a start past the contact's stiffening costs iterations). Measured in "
         "doc/algorithms.md \"Extrapolated start\"",
         choices({"automatic", "none", "linear"}));
  p->set("Max Geometry Iterations", 30,
         "Contact: geometry updates (pairing, normals) allowed per step after Newton "
         "converged with the geometry frozen (>= 0)");
  markPassThrough(p->sublist("NOX", false,
                             "Driver: nox. Passed through to NOX's solver parameters (e.g. "
                             "'Line Search'/'Backtrack'/'Max Iters', 'Printing'/'Output "
                             "Information'); NOX checks them"));
  return p;
}

Teuchos::RCP<const Teuchos::ParameterList> StaticSolverOptions::validAlgorithm() {
  auto p = Teuchos::rcp(new Teuchos::ParameterList("Algorithm"));
  p->set("Method", "partial-newton",
         "How the contact nonlinearities are solved (DESIGN.md §6): 'fixed-point' (geometry, "
         "friction thresholds and statuses are fixed points around Newton), "
         "'generalized-newton' (all three in Newton), 'partial-newton' (geometry a fixed point, "
         "thresholds and statuses in Newton)",
         presetChoices());
  const auto perLoop = choices({"method", "fixed-point", "newton"});
  p->set("Geometry", "method", "Overrides Method for the pairing and normals", perLoop);
  p->set("Friction Threshold", "method", "Overrides Method for the friction threshold mu p",
         perLoop);
  p->set("Contact Statuses", "method",
         "Overrides Method for the contact statuses (free, stick, slip)", perLoop);
  p->set("Max Status Iterations", 30,
         "Status fixed point: updates allowed per geometry update (per step with the geometry "
         "in Newton) that still change a status (>= 0)");
  p->set("Max Threshold Iterations", 30,
         "Threshold fixed point: updates allowed per geometry update (per step with the "
         "geometry in Newton) that still move a threshold (>= 0)");
  p->set("Threshold Tolerance", 1e-6,
         "Threshold fixed point: converged when no threshold moved by more than this times the "
         "largest threshold (> 0)");
  p->set("Cycling Treatment", "combined",
         "What to do at a point detected cycling (doc/algorithms.md): 'none' (count it), "
         "'automatic' (multiply its coefficients by 10, within [1e-2, 1e2] times the local "
         "stiffness E/h; refused for penalty, whose coefficients are the model; Lagrange's "
         "points are forced, its constants only picking the status), 'forced' "
         "(impose its status for the rest of the step: closed for contact cycles, slip for "
         "stick-slip, stick for slip reversal), 'combined' ('forced' for the friction cycles, "
         "'automatic' for the contact cycles, 'forced' for them too with the geometry in "
         "Newton or under the fixed point's status loop). A forced state is checked against the "
         "model's law before a step is accepted",
         choices({"none", "automatic", "forced", "combined"}));
  p->set("Grazing Tolerance", 1e-6,
         "Grazing contact is a 2-3-2-3 cycle with |g^N| + |g^N+1| below this times the point's "
         "size (> 0)");
  p->set("Geometric Terms", "pairing",
         "With the geometry in Newton, the derivatives of the geometry in the tangent: 'full' "
         "(the master point and the smoothed normal: the consistent tangent, quadratic near the "
         "solution, but it diverged from deep first-iterate penetrations on curved masters), "
         "'pairing' (the master point only, the normal held), 'none' (frozen-geometry tangent)",
         choices({"pairing", "full", "none"}));
  p->set("Regularization", "none",
         "'slow-dynamics' adds alpha M / (Time Scale dt)^2 to the tangent, dt the load step's "
         "time increment, M the mass from each material's density (doc/algorithms.md)",
         choices({"none", "slow-dynamics"}));
  Teuchos::ParameterList& sd =
      p->sublist("slow-dynamics", false, "Options of Regularization: slow-dynamics");
  sd.set("Alpha", 1.0, "Factor on the mass matrix (> 0): 1 is the real mass");
  sd.set("Time Scale", 1.0,
         "Physical seconds per unit of load time (> 0): dt = Time Scale times the step's "
         "time increment");
  sd.set("Mass", "consistent", "Mass matrix: 'consistent' or 'lumped' (HRZ diagonal)",
         choices({"consistent", "lumped"}));
  sd.set("Inertia", "residual-and-tangent",
         "'residual-and-tangent': the inertia force alpha M (u - u_n - dt v_n) / dt^2 enters "
         "the residual too (a slow implicit-Euler dynamics, ~0 when the mass is small); "
         "'tangent-only': Newton solves (c M + K) dx = -R with the static residual, so a "
         "converged state is exactly static",
         choices({"residual-and-tangent", "tangent-only"}));
  return p;
}

StaticSolverOptions StaticSolverOptions::from(const Teuchos::ParameterList& loadSteps,
                                              const Teuchos::ParameterList& newton,
                                              const Teuchos::ParameterList& algorithm) {
  StaticSolverOptions o;
  o.steps = loadSteps.get<int>("Steps");
  o.endTime = loadSteps.get<double>("End Time");
  o.maxCuts = loadSteps.get<int>("Max Cuts");
  o.maxIterations = newton.get<int>("Max Iterations");
  o.relativeTolerance = newton.get<double>("Relative Tolerance");
  o.absoluteTolerance = newton.get<double>("Absolute Tolerance");
  o.maxGeometryIterations = newton.get<int>("Max Geometry Iterations");
  o.geometryTolerance = newton.get<double>("Geometry Tolerance");
  o.driver = newton.get<std::string>("Driver");
  o.lineSearch = newton.get<std::string>("Line Search");
  o.lineSearchRetry = newton.get<std::string>("Line Search Retry");
  o.retryMaxIterations = newton.get<int>("Line Search Retry Max Iterations");
  if (o.retryMaxIterations < 0)
    throw std::invalid_argument(
        "Newton/Line Search Retry Max Iterations must be >= 0 (0: twice Max Iterations)");
  if (o.retryMaxIterations == 0) o.retryMaxIterations = 2 * o.maxIterations;
  o.maxUpdate = newton.get<double>("Max Update");
  if (!(o.maxUpdate >= 0))
    throw std::invalid_argument("Newton/Max Update must be >= 0 (0: no such retry)");
  o.stallIterations = newton.get<int>("Stall Iterations");
  if (o.stallIterations < 0)
    throw std::invalid_argument("Newton/Stall Iterations must be >= 0 (0: never)");
  if (newton.isSublist("NOX")) o.nox = newton.sublist("NOX");
  o.predictor = newton.get<std::string>("Predictor");
  o.extrapolation = newton.get<std::string>("Extrapolation");
  if (o.driver == "plain" && o.lineSearch != "Full Step")
    throw std::invalid_argument("Newton/Line Search '" + o.lineSearch +
                                "' needs Newton/Driver: nox (the plain Newton takes full steps)");
  if (o.driver == "plain" && o.nox.numParams() > 0)
    throw std::invalid_argument("Newton/NOX is read by the NOX driver only (Newton/Driver: nox)");
  if (o.steps < 1) throw std::invalid_argument("Load Steps/Steps must be >= 1");
  if (!(o.endTime > 0)) throw std::invalid_argument("Load Steps/End Time must be > 0");
  if (o.maxCuts < 0) throw std::invalid_argument("Load Steps/Max Cuts must be >= 0");
  if (o.maxIterations < 1) throw std::invalid_argument("Newton/Max Iterations must be >= 1");
  if (o.maxGeometryIterations < 0)
    throw std::invalid_argument("Newton/Max Geometry Iterations must be >= 0");
  for (const auto& [key, value] :
       {std::pair<const char*, double>{"Relative Tolerance", o.relativeTolerance},
        {"Absolute Tolerance", o.absoluteTolerance},
        {"Geometry Tolerance", o.geometryTolerance}})
    if (!(value >= 0))
      throw std::invalid_argument(std::string("Newton/") + key + " must be >= 0 (got " +
                                  sci(value) + ")");

  o.method = algorithm.get<std::string>("Method");
  const AlgorithmPreset& preset = algorithmPreset(o.method);
  const auto inNewton = [&](const char* key, bool byMethod) {
    const std::string v = algorithm.get<std::string>(key);
    return v == "method" ? byMethod : v == "newton";
  };
  o.geometryInNewton = inNewton("Geometry", preset.geometryInNewton);
  o.thresholdsInNewton = inNewton("Friction Threshold", preset.thresholdsInNewton);
  o.statusesInNewton = inNewton("Contact Statuses", preset.statusesInNewton);
  o.maxStatusIterations = algorithm.get<int>("Max Status Iterations");
  o.maxThresholdIterations = algorithm.get<int>("Max Threshold Iterations");
  o.thresholdTolerance = algorithm.get<double>("Threshold Tolerance");
  o.cyclingTreatment = algorithm.get<std::string>("Cycling Treatment");
  o.grazingTolerance = algorithm.get<double>("Grazing Tolerance");
  if (o.maxStatusIterations < 0 || o.maxThresholdIterations < 0)
    throw std::invalid_argument("Algorithm/Max Status and Max Threshold Iterations must be >= 0");
  if (!(o.thresholdTolerance > 0) || !(o.grazingTolerance > 0))
    throw std::invalid_argument("Algorithm/Threshold and Grazing Tolerance must be > 0");
  const std::string terms = algorithm.get<std::string>("Geometric Terms");
  o.geometricTerms = terms == "full"      ? GeometricTerms::full
                     : terms == "pairing" ? GeometricTerms::pairing
                                          : GeometricTerms::none;
  const Teuchos::ParameterList& sd = algorithm.sublist("slow-dynamics");
  o.slowDynamics.enabled = algorithm.get<std::string>("Regularization") == "slow-dynamics";
  o.slowDynamics.alpha = sd.get<double>("Alpha");
  o.slowDynamics.timeScale = sd.get<double>("Time Scale");
  o.slowDynamics.lumped = sd.get<std::string>("Mass") == "lumped";
  o.slowDynamics.inertiaInResidual = sd.get<std::string>("Inertia") == "residual-and-tangent";
  if (!(o.slowDynamics.alpha > 0) || !(o.slowDynamics.timeScale > 0))
    throw std::invalid_argument("Algorithm/slow-dynamics/Alpha and Time Scale must be > 0");
  return o;
}

StaticSolver::~StaticSolver() = default;

StaticSolver::StaticSolver(NonlinearSystem& problem, ContactControls* controls,
                           NewtonMethod& newton, StaticSolverOptions options, LinearSolver* solver,
                           NewtonMethod* retry)
    : problem_(problem),
      controls_(controls),
      newton_(newton),
      retry_(retry),
      options_(std::move(options)),
      solver_(solver),
      detector_(options_.grazingTolerance),
      loops_(composeLoops(options_, problem, controls)),
      slowDynamics_(options_.slowDynamics) {
  slowDynamics_.requireMass(problem_);
  if (options_.lineSearchRetry == "never") retry_ = nullptr;
  if (controls_)
    controls_->setGeometricTerms(options_.geometryInNewton ? options_.geometricTerms
                                                           : GeometricTerms::none);
}

bool StaticSolver::statusLoopOutsideNewton() const {
  for (const auto& loop : loops_)
    if (loop->name() == "statuses" && !loop->inNewton()) return true;
  return false;
}

int StaticSolver::treatCycling(const std::vector<CyclingEvent>& events, StepReport& sr) {
  int changed = 0;
  for (const CyclingEvent& e : events) {
    ++sr.cycling[static_cast<int>(e.kind)];
    controls_->markCycling(e.point, static_cast<int>(e.kind));
    if (!treating_ || options_.cyclingTreatment == "none") continue;
    const bool frictionCycle =
        e.kind == CyclingKind::StickSlip || e.kind == CyclingKind::SlipReversal;
    // 'combined': no coefficient breaks a friction cycle (in 2D the slip piece has no
    // tangential stiffness whatever r_t), so those are forced; a contact cycle has its
    // coefficients scaled, except with the geometry in Newton, where a scaled r_n also scales
    // the geometric terms and the cycles multiplied (Cattaneo-Mindlin, generalized Newton: 148
    // sub-cycling events and no convergence): forced there too (doc/algorithms.md, "Cycling").
    // And under a status fixed point, whose frozen statuses no coefficient changes: SSNV128's
    // fixed point cycled through 30 status updates (statuses-not-converged); forced, it
    // converges (hertz-2d-two-body 17 -> 18 iterations, cattaneo-mindlin-2d 66 -> 77).
    // 'automatic' with Lagrange: its constants only pick the status, so the Newton steps of a
    // cycle do not see them and scaling breaks nothing (pad-2d: 22 sub-cycling and 37
    // stick-slip events, |R| 9e6 at max-iterations, where the augmented Lagrangian converges in
    // 16): such a point is forced.
    const bool force =
        options_.cyclingTreatment == "forced" ||
        (options_.cyclingTreatment == "combined" &&
         (frictionCycle || options_.geometryInNewton || statusLoopOutsideNewton())) ||
        (options_.cyclingTreatment == "automatic" && !controls_->scalingChangesForces(e.point));
    if (force) {
      forcedPoints_.push_back(e.point);
      const int status = e.kind == CyclingKind::StickSlip      ? 2
                         : e.kind == CyclingKind::SlipReversal ? 1
                                                               : kForcedClosed;
      controls_->forceStatus(e.point, status);
      detector_.forget(e.point);
      ++changed;
    } else if (controls_->scaleCoefficients(e.point, 10.0)) {
      ++changed;
    }
  }
  return changed;
}

bool StaticSolver::forcedStateHolds(const Vector& x, double t, double target, Vector& residual) {
  if (forcedPoints_.empty() || !treating_) return true;
  treating_ = false;
  controls_->releaseForcedStatuses();
  // A fixed point whose frozen state the forcing set (a forced point's frozen status is the
  // forced one) takes it from the model's law again here.
  bool revised = false;
  for (const auto& loop : loops_)
    if (!loop->inNewton() && loop->reviseForcedState(x, t)) revised = true;
  problem_.assemble(x, t, &residual, false);
  // The contact equations as forces too (ContactControls::constraintResidual): a stick-slip
  // point forced to slip with a traction of 2.4 mu p (SSNV128 with lagrange) leaves its friction
  // row at w (|Lambda| - 1), a number far below a target in forces.
  forcedResidual_ = std::max(residual.norm2(), controls_->constraintResidual());
  return !revised && forcedResidual_ <= target;
}

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

double StaticSolver::extrapolatedStart(const Vector& u, Vector& x, double t, Vector& residual) {
  const bool wanted =
      options_.extrapolation == "linear" || (options_.extrapolation == "automatic" &&
                                             (controls_ == nullptr || statusLoopOutsideNewton()));
  if (!wanted) return -1;
  problem_.assemble(x, t, &residual, false);
  if (!problem_.assemblyFailure().code.empty()) {
    extrapolation_.skipStep();
    return -1;
  }
  extrapolation_.beginStep(residual);
  const double a = extrapolation_.factor();
  if (a == 0) return -1;
  const double plain = residual.norm2();
  extrapolation_.extrapolate(u, a, x);
  problem_.applyDirichlet(t, x);  // the prescribed values at t, not extrapolated
  problem_.updateGeometry(x, t);
  return plain;
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

bool StaticSolver::solveStep(NewtonMethod& newton, const Vector& u, Vector& x, StepReport& sr,
                             RunReport& report, const IterationCallback& onIteration,
                             double maxUpdate) {
  const double t = sr.time;
  x.assign(u);
  problem_.applyDirichlet(t, x);
  forcedPoints_.clear();
  treating_ = true;
  if (controls_) {
    controls_->releaseTreatments();
    detector_.reset();
  }
  for (const auto& loop : loops_)
    loop->beginStep();
  slowDynamics_.beginStep(problem_, t);
  problem_.updateGeometry(x, t);
  auto residual = problem_.createVector();
  const double plainStart = extrapolatedStart(u, x, t, *residual);
  const bool extrapolated = plainStart >= 0;
  const Prediction prediction = extrapolated ? Prediction{} : predict(u, x, sr, report);
  if (prediction.done) problem_.updateGeometry(x, t);
  // The step's reference residual, and the statuses the fixed points start from: a predicted
  // step has its reference already, and without contact nothing else reads this assembly. An
  // extrapolated step keeps the plain start's: the tolerance stays relative to the increment's
  // load, not to how well the extrapolation guessed.
  double reference = extrapolated ? plainStart : prediction.residual;
  if (!prediction.done || controls_) {
    problem_.assemble(x, t, residual.get(), false);
    if (!prediction.done && !extrapolated) reference = residual->norm2();
  }
  // The fixed points start from the statuses and thresholds of the predictor.
  for (const auto& loop : loops_)
    if (!loop->inNewton()) loop->freeze();

  const auto fail = [&](const std::string& failure, const std::string& message) {
    report.failure = failure;
    report.message = message + " at step " + std::to_string(sr.step) + " (t = " + sci(t) + ")";
    if (failure == kSingularTangent) report.message += singularTangentRemedy();
    if (!treating_ && !forcedPoints_.empty()) {
      // The forced treatment had converged on its modified law, and the model's own law
      // failed from there: name that, and the points.
      std::vector<std::size_t> points = forcedPoints_;
      std::sort(points.begin(), points.end());
      points.erase(std::unique(points.begin(), points.end()), points.end());
      std::string list;
      for (std::size_t i = 0; i < points.size() && i < 10; ++i)
        list += (i ? ", " : "") + std::to_string(points[i]);
      if (points.size() > 10) list += ", ...";
      report.failure = "degraded-contact";
      report.message =
          "the forced cycling treatment converged to a state that violates the "
          "contact law at its " +
          std::to_string(points.size()) + " forced point(s) (contact points " + list +
          "; |R| = " + sci(forcedResidual_) +
          " with the law restored), and Newton from there without the treatment "
          "failed (" +
          failure + ": " + report.message + ")";
    }
    return false;
  };
  if (!prediction.failure.empty()) return fail(prediction.failure, prediction.message);
  // The solid-alone predictor where the tangent one does not start a contact model's step.
  const bool solidAlone = !prediction.done && controls_ && options_.statusesInNewton &&
                          (options_.predictor == "solid-alone" ||
                           (options_.predictor == "automatic" && u.normInf() == 0)) &&
                          reference > options_.absoluteTolerance && stepSolidAlone(x, t, sr);
  if (solidAlone) ++report.linearSolves;
  int solves = prediction.done || solidAlone ? 1 : 0;
  IterateProgress progress;
  progress.step = sr.step;
  progress.time = t;
  progress.attempt = attempt_;
  if (onIteration && (prediction.done || solidAlone)) {
    progress.residual = prediction.done ? prediction.residual : reference;
    onIteration(progress);
  }
  NewtonMethod::Observer observer;
  observer.treat = [&](int) {
    progress.treatedPoints =
        controls_ ? treatCycling(detector_.observe(controls_->pointStates()), sr) : 0;
    return progress.treatedPoints > 0;
  };
  observer.report = [&](int iteration, double norm) {
    if (const int signal = interruptionAgreed(mpiComm_)) throw Interrupted{signal};
    sr.residual = norm;
    progress.iteration = solves + iteration;
    progress.residual = norm;
    if (onIteration) onIteration(progress);
    progress.treatedPoints = 0;
  };
  NewtonRequest request;
  request.time = t;
  request.target = std::max(options_.absoluteTolerance, options_.relativeTolerance * reference);
  request.maxIterations = &newton == retry_ ? options_.retryMaxIterations : options_.maxIterations;
  request.geometryInNewton = options_.geometryInNewton;
  request.maxUpdate = maxUpdate;
  request.stallIterations = maxUpdate > 0 ? 0 : options_.stallIterations;
  for (;;) {
    const NewtonOutcome outcome = newton.solve(x, request, observer);
    solves += outcome.iterations;
    sr.iterations += outcome.iterations;
    sr.residual = outcome.residual;
    sr.seconds.assembly += outcome.assemblySeconds;
    sr.seconds.linearSolve += outcome.linearSolveSeconds;
    report.linearSolves += outcome.iterations;
    report.limitedUpdates += outcome.limitedUpdates;
    report.unevaluableHalvings += outcome.unevaluableHalvings;
    sr.longestUpdate = std::max(sr.longestUpdate, outcome.longestUpdate);
    if (!outcome.failure.empty()) {
      // A NaN residual from an iterate the solid could not evaluate: say which and where.
      const AssemblyFailure assembly = problem_.assemblyFailure();
      if (!assembly.code.empty()) return fail(assembly.code, assembly.message);
      return fail(outcome.failure, outcome.message);
    }
    // The innermost fixed point whose update moves restarts Newton; the loops outside it are
    // not updated until it settles.
    std::size_t k = 0;
    while (k < loops_.size() && (loops_[k]->inNewton() || !loops_[k]->update(x, t)))
      ++k;
    if (k == loops_.size()) {
      // A forced state that violates the model's law is not a solution: Newton goes on from
      // it with the law restored (near a solution, it converges in a few iterations).
      if (forcedStateHolds(x, t, request.target, *residual)) return true;
      continue;
    }
    FixedPointLoop& moved = *loops_[k];
    // A status that flips from one fixed-point update to the next cycles too.
    if (moved.changesStatuses()) treatCycling(detector_.observe(controls_->pointStates()), sr);
    if (moved.updates() == moved.maxUpdates()) return fail(moved.failure(), moved.failureMessage());
    moved.recordUpdate(sr);
    if (moved.renewsInnerCaps())
      for (std::size_t inner = 0; inner < k; ++inner)
        loops_[inner]->renewCap();
    const FixedPointLoop::MovedStateTest test = moved.testMovedState(x, t, reference, *residual);
    if (test.tested) {
      sr.residual = test.residual;
      if (test.residual <= test.target && forcedStateHolds(x, t, test.target, *residual))
        return true;
    }
  }
}

namespace {
// Whether a step failed because its iterates did not settle or went where the system cannot be
// evaluated (an element inverted, a contact facet without a dual basis: NOX's backtracking
// rejects such a trial point and halves the step, UnevaluableIterate.NoxBacktracking...), which
// a line search may change; not a singular tangent.
bool iteratesFailedToConverge(const std::string& failure) {
  for (const char* name :
       {"max-iterations", "diverged", "degraded-contact", "statuses-not-converged",
        "thresholds-not-converged", "geometry-not-converged", "nan-detected",
        "contact-geometry-failed", "inverted-element", "material-update-failed"})
    if (failure == name) return true;
  return false;
}

// A step attempt's counts into the run's, converged or not.
void account(const StepReport& sr, RunReport& report) {
  report.iterations += sr.iterations;
  report.statusIterations += sr.statusIterations;
  report.thresholdIterations += sr.thresholdIterations;
  report.geometryIterations += sr.geometryIterations;
  for (int k = 0; k < kCyclingKinds; ++k)
    report.cycling[k] += sr.cycling[k];
  report.seconds.assembly += sr.seconds.assembly;
  report.seconds.linearSolve += sr.seconds.linearSolve;
}
}  // namespace

double StaticSolver::stepEnd(double t, double dt) const {
  // The next nominal time k End Time / Steps after t, and the first landing time before it:
  // after cuts and regrowth the steps drift off the nominal grid, and a step from t = 0.9375
  // to 1.1875 passed the peak of the hex27 tube's load table at t = 1 (Backtrack run: 297 N of
  // residual contact force where the steps that land on t = 1 give 358 N).
  const double nominal = options_.endTime / options_.steps;
  const double margin = 1e-9 * nominal;
  double stop = (std::floor(t / nominal + 1e-9) + 1) * nominal;
  if (stop > options_.endTime - margin) stop = options_.endTime;  // no sliver of a last step
  for (double landing : options_.landingTimes)
    if (landing > t + margin && landing < stop - margin) stop = landing;
  return t + dt > stop - margin ? stop : t + dt;
}

RunReport StaticSolver::run(Vector& u, const StepCallback& onStep,
                            const IterationCallback& onIteration, const RunStart& start) {
  RunReport report;
  report.startFrom(start.totals);
  mpiComm_ = rawMpiComm(u.getMap()->getComm());
  if (controls_ && !start.fromState) controls_->seedInitialStatuses(u, start.time);
  if (start.increment && start.load) extrapolation_.restore(*start.increment, *start.load);
  slowDynamics_.start(u, start.time);
  // However the run ends, what runs after it (outputs, diagnostics) sees the static system.
  struct StaticAfterRun {
    const SlowDynamics& slowDynamics;
    NonlinearSystem& system;
    ~StaticAfterRun() { slowDynamics.end(system); }
  } staticAfterRun{slowDynamics_, problem_};
  auto x = problem_.createVector();
  const double nominal = options_.endTime / options_.steps;
  const double smallest = std::ldexp(nominal, -options_.maxCuts);
  double t = start.time, dt = start.stepSize > 0 ? start.stepSize : nominal;
  int cuts = 0;  // in a row, for the current step
  const double updateLimit = options_.maxUpdate * problem_.modelSize();
  while (t < options_.endTime * (1 - 1e-12)) {
    StepReport sr;
    sr.step = start.step + report.steps + 1;
    sr.cuts = cuts;
    sr.time = stepEnd(t, dt);
    const double h = sr.time - t;  // dt, or less where the step lands on a time it must not pass
    // The floor: a run whose every step converges only after a cut would otherwise halve dt
    // without end and creep towards a time it never reaches (measured: the elasto-plastic
    // 3D ironing, 1e-5 steps at t = 0.8124 after an hour).
    const bool atFloor = h / 2 < smallest * (1 - 1e-9);
    const bool lastTry = cuts == options_.maxCuts || atFloor;
    bool ok = false;
    try {
      ok = solveStep(newton_, u, *x, sr, report, onIteration);
      // A failed step solved again another way from its start (sr counts every attempt); a
      // failed second try reports the first attempt's failure (the one a table of methods
      // compares), the second's in its message.
      const auto solveAgain = [&](NewtonMethod& method, double maxUpdate, const char* attempt,
                                  const std::string& how) {
        const std::string failure = report.failure, message = report.message;
        attempt_ = attempt;
        const bool solved = solveStep(method, u, *x, sr, report, onIteration, maxUpdate);
        attempt_ = "";
        if (solved) {
          report.failure.clear();
          report.message.clear();
          return true;
        }
        report.message =
            message + "; solved again " + how + ": " + report.failure + ": " + report.message;
        report.failure = failure;
        return false;
      };
      // A contact Newton that failed with full steps (cycling statuses, overshooting iterates)
      // often converges at the same increment when each step must decrease ||R||: the
      // frictional hex27 tube's unloading failed down to the smallest step and converges in 9
      // iterations so (doc/algorithms.md "Line search retry").
      if (!ok && retry_ && (lastTry || options_.lineSearchRetry == "every-failure") &&
          iteratesFailedToConverge(report.failure)) {
        ++report.lineSearchRetries;
        ok = sr.lineSearchRetry =
            solveAgain(*retry_, 0, "line-search retry", "with the Backtrack line search");
      }
      // Full steps that failed through an update longer than the limit: a tangent nearly
      // singular (a perfectly plastic tube at its limit load before it meets the hole) threw the
      // iterate out, and ||R|| is flat along that mode, so the line search creeps; with the
      // updates limited Newton walks along it (doc/algorithms.md "Update limit"). Whatever the
      // failure (iterates that did not settle; a tangent that cannot be factorized, or an
      // element inverted, at a far-flung iterate); where no update was that long, the same
      // steps would fail again. After the line-search retry, so that what it saved is
      // unchanged.
      if (!ok && updateLimit > 0 && sr.longestUpdate > updateLimit)
        ok = sr.updateLimitRetry = solveAgain(newton_, updateLimit, "update-limit retry",
                                              "with updates limited to " + sci(updateLimit));
    } catch (const Interrupted& i) {
      // The last converged step stays the result; the summary says why the run stopped.
      report.failure = "interrupted";
      report.message = std::string("interrupted by ") +
                       (i.signal == SIGINT ? "SIGINT" : "SIGTERM") +
                       " during the step to t = " + sci(sr.time) + "; the results are those of " +
                       "the last converged step";
      report.interruptSignal = i.signal;
      report.iterations += sr.iterations;
      return report;
    }
    account(sr, report);
    if (!ok) {
      if (lastTry) {
        if (options_.maxCuts > 0) {
          report.failure = "step-too-small";
          report.message =
              "the step to t = " + sci(sr.time) + " still failed " +
              (cuts == options_.maxCuts
                   ? "after " + std::to_string(cuts) + " cuts (Load Steps/Max Cuts)"
                   : "at dt = " + sci(dt) + ", the smallest step (End Time / Steps / 2^Max Cuts)") +
              "; last: " + report.message;
        } else if (iteratesFailedToConverge(report.failure)) {
          // A failed step is not cut by default (studies count failures); say how to cut it.
          report.message +=
              " (Load Steps/Max Cuts = 0: the step was not cut; a shorter step "
              "may pass, e.g. Max Cuts: 4)";
        }
        return report;
      }
      ++cuts;
      ++report.cuts;
      dt = h / 2;
      report.failure.clear();
      report.message.clear();
      continue;
    }
    extrapolation_.record(u, *x);
    sr.increment = extrapolation_.increment();
    sr.load = extrapolation_.load();
    u.assign(*x);
    slowDynamics_.commit(problem_, u, sr.time);
    problem_.commitState(u, sr.time);
    ++report.steps;
    sr.nextStepSize = cuts == 0 ? std::min(2 * dt, nominal) : dt;
    sr.run = report.totals();
    const auto t0 = std::chrono::steady_clock::now();
    if (onStep) onStep(sr, u);
    report.seconds.output += secondsSince(t0);
    t = sr.time;
    dt = sr.nextStepSize;
    cuts = 0;
  }
  report.converged = true;
  return report;
}

}  // namespace contactlab
