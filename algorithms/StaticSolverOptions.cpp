// StaticSolverOptions: the scene's Load Steps, Newton and Algorithm sections, validated, with a
// doc string per parameter (`contactlab list`, doc/scenes.md).
#include "algorithms/AlgorithmPresets.hpp"
#include "algorithms/StaticSolver.hpp"
#include "base/NumberText.hpp"
#include "core/io/ParameterValidation.hpp"

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace contactlab {
namespace {

Teuchos::RCP<Teuchos::StringValidator> choices(std::initializer_list<std::string> names) {
  return Teuchos::rcp(new Teuchos::StringValidator(Teuchos::Array<std::string>(names)));
}

Teuchos::RCP<Teuchos::StringValidator> presetChoices() {
  Teuchos::Array<std::string> names;
  for (const AlgorithmPreset& preset : algorithmPresets())
    names.push_back(preset.name);
  return Teuchos::rcp(new Teuchos::StringValidator(names));
}

// Load Steps/Times into o.times; with it, End Time is its last entry (given or not) and Steps
// must be left at 1.
void readTimes(const Teuchos::ParameterList& loadSteps, StaticSolverOptions& o) {
  for (double t : loadSteps.get<Teuchos::Array<double>>("Times")) {
    if (!(t > (o.times.empty() ? 0.0 : o.times.back())) || !std::isfinite(t))
      throw std::invalid_argument(
          "Load Steps/Times must be finite, > 0 and increase (" + numberText(t) +
          (o.times.empty() ? "" : " after " + numberText(o.times.back())) + ")");
    o.times.push_back(t);
  }
  if (o.times.empty()) return;
  if (o.steps != 1)
    throw std::invalid_argument(
        "Load Steps: Steps and Times both given; Times sets the steps (one ends on each entry): "
        "leave Steps out, or at 1");
  const double end = o.times.back();
  const bool endGiven = !loadSteps.getEntry("End Time").isDefault();
  if (endGiven && std::abs(o.endTime - end) > 1e-12 * end)
    throw std::invalid_argument("Load Steps/End Time (" + numberText(o.endTime) +
                                ") is not the last entry of Load Steps/Times (" + numberText(end) +
                                "): leave End Time out, or end Times there");
  o.endTime = end;
}

}  // namespace

StaticSolverOptions::NominalStep StaticSolverOptions::nominalStep(double t) const {
  NominalStep s;
  if (times.empty()) {
    const double nominal = endTime / steps;
    s.end = (std::floor(t / nominal + 1e-9) + 1) * nominal;
    if (s.end > endTime - 1e-9 * nominal) s.end = endTime;  // no sliver of a last step
    s.length = nominal;
    return s;
  }
  const auto next = std::upper_bound(times.begin(), times.end(), t + 1e-9 * endTime);
  const auto end = next == times.end() ? times.end() - 1 : next;
  s.end = *end;
  s.length = s.end - (end == times.begin() ? 0.0 : *(end - 1));
  return s;
}

Teuchos::RCP<const Teuchos::ParameterList> StaticSolverOptions::validLoadSteps() {
  auto p = Teuchos::rcp(new Teuchos::ParameterList("Load Steps"));
  p->set("Steps", 1, "Number of equal load steps from t = 0 to End Time (>= 1)");
  p->set("End Time", 1.0, "Pseudo-time at the end of the load (> 0); ramps reach 1 there");
  p->set("Times", Teuchos::Array<double>(),
         "The instants the steps end on, in place of Steps equal ones (code_aster's "
         "DEFI_LIST_REEL): increasing, > 0, e.g. [0.01, 0.05, 0.15, 0.4, 1]; the last is the "
         "end of the load (End Time, which may be left out). Each interval between two entries "
         "(the first from 0) is then one nominal step. Steps must be left at 1");
  p->set("Max Cuts", 0,
         "A step that fails is cut in two and retried, up to this many times in a row (>= 0; "
         "0: a failed step ends the run). After a step converges without a cut the step "
         "doubles again, up to its nominal step (End Time / Steps, or the interval of Times it "
         "lies in). No step is cut below its nominal step / 2^Max Cuts: a run whose every step "
         "needs a cut ends there (step-too-small). Cut or not, a step ends on every nominal "
         "step's end (a multiple of End Time / Steps, or an entry of Times), kink of a load "
         "function (a ramp's start and stop, a table's times) and Output/Contact Times entry it "
         "would pass");
  return p;
}

Teuchos::RCP<const Teuchos::ParameterList> StaticSolverOptions::validNewton() {
  auto p = Teuchos::rcp(new Teuchos::ParameterList("Newton"));
  p->set("Max Iterations", 20,
         "Newton iterations allowed per Newton solve (>= 1); a step runs "
         "one solve per fixed-point iteration");
  p->set("Relative Tolerance", 1e-8,
         "Converged when ||R|| <= Relative Tolerance * the larger of ||R at the step's first "
         "iterate|| and the norm of the internal forces there (the loads and the reactions "
         "that balance them), and no contact status changed at the last iterate; a step that "
         "holds the load (its first ||R|| below 1e-3 of the last loaded step's) is measured "
         "against 1e-3 of that one's at least");
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
  p->set("Fixed Point Forcing", 1e-2,
         "Contact, a fixed point (statuses, thresholds or geometry, as the Algorithm says): "
         "while it still moves, the Newton solve after one of its updates stops at Fixed Point "
         "Forcing times the residual the update left (never below the step's own target), "
         "since the next update moves the residual by more than that; a step ends only on a "
         "solve to the step's target. In [0, 1); 0: every solve to the step's target "
         "(doc/algorithms.md \"Inexact solves between fixed-point updates\")");
  p->set("Geometry Retry", true,
         "A load step whose geometric fixed point diverged (the residual at the updated "
         "geometry ended above the step's first and 100 times above its lowest: a master whose "
         "normal turns as it dents, frozen at each update) is solved again from its start with "
         "the geometry in Newton and its full terms (Algorithm/Geometric Terms: full, the "
         "consistent tangent; not symmetric on node-to-segment, so MUMPS' Mode automatic turns "
         "to general for the rest of the run), before the line-search retry, which then keeps "
         "the geometry in Newton. Where the geometry is in Newton already (generalized "
         "Newton) with fewer terms (Geometric Terms: pairing or none) and a node-to-segment "
         "zone (whose master normal the full terms add), a step the line-search retry did not "
         "save is solved again by it with the full terms "
         "(doc/algorithms.md \"Geometry retry\")");
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
         "in doc/algorithms.md. Steps driven by loads alone start from u_n with 'tangent'. "
         "A step that Newton/Extrapolation starts from the last step's extrapolation takes "
         "no predictor",
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
         "How the contact nonlinearities are solved (doc/theory.md): 'fixed-point' (geometry, "
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
  p->set("Threshold Tolerance", 1e-3,
         "Threshold fixed point: converged when no threshold moved by more than this times the "
         "largest threshold (> 0). It bounds each threshold's last move, not the forces' error: "
         "1e-3 ends within 1e-6 of 1e-6's state in 13-46 % fewer Newton iterations on the "
         "frictional scenes (doc/performance.md)");
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
  readTimes(loadSteps, o);
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
  o.geometryRetry = newton.get<bool>("Geometry Retry");
  o.fixedPointForcing = newton.get<double>("Fixed Point Forcing");
  if (!(o.fixedPointForcing >= 0 && o.fixedPointForcing < 1))
    throw std::invalid_argument("Newton/Fixed Point Forcing must be in [0, 1) (got " +
                                scientificText(o.fixedPointForcing) +
                                "; 0: every solve to the step's target)");
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
                                  scientificText(value) + ")");

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

}  // namespace contactlab
