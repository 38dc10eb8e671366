#include "apps/RunCommand.hpp"

#include "algorithms/PatternCriticalFriction.hpp"
#include "algorithms/RunStatic.hpp"
#include "apps/DefaultScene.hpp"
#include "apps/RunProgress.hpp"
#include "apps/SceneModel.hpp"
#include "base/InputError.hpp"
#include "core/io/CsvWriter.hpp"
#include "core/io/JsonWriter.hpp"
#include "core/io/OutputFolder.hpp"
#include "core/io/VtkSeriesWriter.hpp"
#include "core/problem/CollectiveError.hpp"
#include "core/problem/Problem.hpp"
#include "formulations/ContactProblem.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sys/resource.h>
#include <unistd.h>

namespace contactlab {
namespace {

double peakMemoryMB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // Linux reports kB
}

JsonValue toJson(const Teuchos::ParameterList& list) {
  JsonValue object = JsonValue::object();
  for (auto it = list.begin(); it != list.end(); ++it) {
    const auto& entry = list.entry(it);
    const std::string& key = list.name(it);
    if (entry.isList())
      object.set(key, toJson(list.sublist(key)));
    else if (entry.isType<double>())
      object.set(key, Teuchos::getValue<double>(entry));
    else if (entry.isType<int>())
      object.set(key, Teuchos::getValue<int>(entry));
    else if (entry.isType<bool>())
      object.set(key, Teuchos::getValue<bool>(entry));
    else if (entry.isType<std::string>())
      object.set(key, Teuchos::getValue<std::string>(entry));
    else if (entry.isType<Teuchos::Array<double>>())
      object.set(key,
                 JsonValue::array(Teuchos::getValue<Teuchos::Array<double>>(entry).toVector()));
    else if (entry.isType<Teuchos::Array<int>>())
      object.set(key, JsonValue::array(Teuchos::getValue<Teuchos::Array<int>>(entry).toVector()));
  }
  return object;
}

// A typed section as {"type": name, "parameters": {...}}.
JsonValue typedSection(const Teuchos::ParameterList& section) {
  const std::string type = section.get<std::string>("Type");
  return JsonValue::object().set("type", type).set("parameters", toJson(section.sublist(type)));
}

// Bad input: one sentence on stderr, exit code 2.
int reportInputError(const std::exception& e, bool root) {
  if (root) std::cerr << "contactlab: error: " << e.what() << "\n";
  return 2;
}

// A follower pressure's load stiffness is not symmetric: a solver that assumes symmetry would
// solve another system (MUMPS reads one triangle, CG loses its guarantees). Refused before
// anything runs, the same on every rank (both sides are).
void checkSymmetry(const Problem& problem, const LinearSolver& solver, const std::string& where) {
  const std::string assumption = solver.symmetryAssumption();
  if (problem.followerLoads().empty() || assumption.empty()) return;
  throw InputError(where + ": Linear Solver/" + solver.name() + ": " + assumption + ", but load '" +
                   problem.followerLoads().front() +
                   "' is a pressure that follows the deformation of a finite-strain body, and "
                   "its load stiffness makes the tangent not symmetric; use a setting that takes "
                   "any matrix, or Follower: false on the load (a dead pressure on the reference "
                   "facets)");
}

// Whether the assembled tangent is symmetric: every material's, no follower load, every
// contact law's for its friction, and no node-to-segment geometric terms (the geometry in
// Newton with Geometric Terms pairing or full differentiate the normal along one side only).
bool tangentIsSymmetric(const SceneModel& sm, const Problem& problem) {
  if (!problem.followerLoads().empty()) return false;
  for (const auto& [block, material] : sm.model.materials)
    if (!material->symmetricTangent()) return false;
  const StaticSolverOptions& o = sm.solverOptions;
  const bool geometricTerms = o.geometryInNewton && o.geometricTerms != GeometricTerms::none;
  const int nt = sm.model.mesh->dim - 1;
  for (const ContactZone& zone : sm.contact) {
    if (!zone.law->symmetricJacobian(zone.friction > 0 ? nt : 0)) return false;
    if (geometricTerms && zone.discretization == Discretization::nodeToSegment) return false;
  }
  return true;
}

// Whether some contact zone has friction (mu > 0): the uniqueness check has something to check.
bool hasFriction(const SceneModel& sm) {
  for (const auto& zone : sm.contact)
    if (zone.friction > 0) return true;
  return false;
}

// MUMPS' Mode 'automatic' (the default): LDL^T with 2x2 pivots (SYM = 2) on a symmetric
// tangent, about 1.8x faster than LU on a 3D Hertz model of 125 571 dofs (doc/performance.md),
// LU otherwise. Written into the scene, so summary.json reports the mode used.
void resolveSolverMode(Teuchos::ParameterList& scene, bool symmetric) {
  Teuchos::ParameterList& section = scene.sublist("Linear Solver");
  if (section.get<std::string>("Type") != "mumps") return;
  Teuchos::ParameterList& mumps = section.sublist("mumps");
  if (mumps.get<std::string>("Mode", "automatic") != "automatic") return;
  mumps.set("Mode", symmetric ? "symmetric-indefinite" : "general");
}

}  // namespace

// The status pattern of the converged state x at time t: its critical friction factor, and the
// critical mu of every frictional zone (printed on rank 0). Null when there is nothing to check.
namespace {

JsonValue criticalMuSummary(const SceneModel& sm, ContactProblem* contact, const Vector& x,
                            double t, int convergedSteps, const Teuchos::RCP<const Comm>& comm) {
  const bool root = comm->getRank() == 0;
  std::string why;
  if (!contact)
    why = "the scene has no contact";
  else if (!hasFriction(sm))
    why = "no contact zone has friction (mu = 0)";
  else if (convergedSteps == 0)
    why = "no load step converged";
  if (!why.empty()) {
    if (root) std::cout << "contactlab: critical-mu: not computed: " << why << "\n";
    return JsonValue::object().set("computed", false).set("reason", why);
  }
  // The scene's solver with determinants (their signs decide local uniqueness).
  const std::unique_ptr<LinearSolver> solver = buildUniquenessCheckSolver(sm, comm);
  const auto start = std::chrono::steady_clock::now();
  const UniquenessCheck c = checkUniqueness(*contact, *contact, *solver, x, t,
                                            sm.criticalMuTolerance, sm.criticalMuMaxPatterns);
  JsonValue zones = JsonValue::object();
  for (const auto& zone : sm.contact)
    if (zone.friction > 0)
      zones.set(zone.name, std::isinf(c.scale) ? JsonValue() : JsonValue(zone.friction * c.scale));
  const std::string verdict = c.singularPatterns > 0 ? "possibly non-unique (a singular Jacobian)"
                              : !c.sameSign          ? "possibly non-unique"
                                                     : "locally unique";
  if (root) {
    std::cout << "contactlab: critical-mu: converged state at t = " << t << ": "
              << c.ambiguousPoints << " ambiguous point(s), " << c.patterns
              << " status pattern(s) examined (" << c.choice << "; " << c.updatedPatterns
              << " by updates of the converged pattern's factorization): " << verdict;
    if (!c.sameSign && !c.breakingPattern.empty())
      std::cout << "; the sign changes at " << c.breakingPattern;
    std::cout << "\n";
    const auto factor = [](double s) {
      return std::isinf(s) ? std::string("none") : std::to_string(s);
    };
    std::cout << "contactlab: critical-mu: critical factor of the adjacent patterns "
              << factor(c.localScale) << ", of the contact set slipping " << factor(c.slipScale)
              << "\n";
    if (std::isinf(c.scale)) {
      std::cout << "contactlab: critical-mu: no critical mu (det J(s mu) has no positive real "
                   "root on these patterns)\n";
    } else {
      std::cout << "contactlab: critical-mu: critical factor " << c.scale << " on mu";
      for (const auto& zone : sm.contact)
        if (zone.friction > 0)
          std::cout << "; " << zone.name << ": mu = " << zone.friction
                    << ", mu_crit = " << zone.friction * c.scale
                    << (c.scale <= 1.0 ? " (mu >= mu_crit: possibly non-unique)" : "");
      std::cout << "\n";
    }
  }
  JsonValue out =
      JsonValue::object()
          .set("computed", true)
          .set("time", t)
          .set("seconds",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count())
          .set("friction_rows", c.frictionRows)
          .set("ambiguous_points", c.ambiguousPoints)
          .set("patterns_examined", c.patterns)
          .set("patterns_updated", c.updatedPatterns)
          .set("pattern_choice", c.choice)
          .set("verdict", verdict)
          .set("singular_patterns", c.singularPatterns)
          .set("breaking_pattern",
               c.breakingPattern.empty() ? JsonValue() : JsonValue(c.breakingPattern))
          .set("factor", std::isinf(c.scale) ? JsonValue() : JsonValue(c.scale))
          .set("adjacent_factor", std::isinf(c.localScale) ? JsonValue() : JsonValue(c.localScale))
          .set("slipping_factor", std::isinf(c.slipScale) ? JsonValue() : JsonValue(c.slipScale))
          .set("zones", zones);
  return out;
}

}  // namespace

int runCommand(const RunOptions& options, const Teuchos::RCP<const Comm>& comm) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(clock::now() - start).count(); };
  const bool root = comm->getRank() == 0;

  // 1. Read, validate and build everything that can fail on bad input: nothing is written yet.
  SceneModel sm;
  std::unique_ptr<Problem> problem;
  std::unique_ptr<ContactProblem> contact;
  std::unique_ptr<LinearSolver> solver;
  try {
    SceneFile file = options.scenePath.empty()
                         ? readSceneText(kDefaultScene, "<default scene>", options.overrides)
                         : readSceneFile(options.scenePath, options.overrides);
    sm = loadScene(std::move(file), comm);
    try {
      problem = std::make_unique<Problem>(sm.model, comm);
    } catch (const InputError& e) {
      const std::string message = e.what();
      if (message.find(sm.scene.path) != std::string::npos) throw;
      throw InputError(sm.scene.path + ": " + message);
    }
    if (!sm.contact.empty()) {
      try {
        contact = std::make_unique<ContactProblem>(*problem, sm.contact);
        // Pairs the surfaces in the initial state: an initial penetration deeper than an
        // element is refused here, before anything runs (same verdict on every rank).
        auto x0 = contact->createVector();
        contact->updateGeometry(*x0, 0.0);
      } catch (const InputError& e) {
        throw InputError(sm.scene.path + ": Contact: " + e.what());
      }
    }
    resolveSolverMode(*sm.scene.params, tangentIsSymmetric(sm, *problem));
    solver = buildLinearSolver(*sm.scene.params, comm);
    checkSymmetry(*problem, *solver, sm.scene.path);
    // The uniqueness checks need the solver's determinants: a solver without them is refused
    // now, not after the run.
    if (contact && sm.criticalMuCheck) requireDeterminantSolver(sm, "Output/Critical Mu Check");
    if (contact && options.criticalMu && hasFriction(sm))
      requireDeterminantSolver(sm, "critical-mu");
    if (options.validateOnly) {
      if (root)
        std::cout << sm.scene.path << ": valid (" << sm.model.mesh->numNodes() << " nodes, "
                  << sm.model.mesh->numElements() << " elements)\n";
    } else {
      // Before solving: a folder that cannot be written is found now, not after step 1.
      const std::string folder =
          options.outputDirectory.empty() ? sm.outputDirectory : options.outputDirectory;
      collectively(*comm, [&] {
        if (!root) return;
        const std::vector<std::string> stale = prepareOutputFolder(folder);
        if (!stale.empty())
          std::cerr << "contactlab: " << folder << ": removed " << stale.size()
                    << " file(s) of an earlier run\n";
      });
    }
  } catch (const InputError& e) {
    return reportInputError(e, root);
  } catch (const LinearSolverError& e) {
    return reportInputError(e, root);
  }
  if (options.validateOnly) return 0;
  const double setupSeconds = elapsed();

  const std::string outDir =
      options.outputDirectory.empty() ? sm.outputDirectory : options.outputDirectory;
  const auto& params = *sm.scene.params;
  const int steps = sm.solverOptions.steps;
  NonlinearSystem& system = contact ? static_cast<NonlinearSystem&>(*contact) : *problem;
  const long long multipliers = contact ? static_cast<long long>(contact->numMultipliers()) : 0;
  if (root)
    std::cerr << "contactlab: " << sm.scene.name << ": " << problem->dofs().numGlobalDofs()
              << " dofs"
              << (multipliers ? " + " + std::to_string(multipliers) + " multipliers" : "") << " on "
              << comm->getSize() << " rank(s), " << steps << " load step(s)\n";

  // 2. Solve; each converged step is written at once.
  MPI_Comm mpiComm = rawMpiComm(comm);
  std::unique_ptr<VtkSeriesWriter> vtk;
  std::vector<std::string> stepColumns{"step",
                                       "time",
                                       "cuts",
                                       "newton_iterations",
                                       "status_iterations",
                                       "threshold_iterations",
                                       "geometry_iterations",
                                       "linear_solves",
                                       "residual",
                                       "contact_points",
                                       "stick_points",
                                       "slip_points",
                                       "cycling_events"};
  for (int k = 1; k < kCyclingKinds; ++k)
    stepColumns.push_back(std::string("cycling_") + cyclingKindName(static_cast<CyclingKind>(k)));
  for (const char* c :
       {"condition_estimate", "assembly_s", "pairing_s", "contact_s", "linear_solve_s"})
    stepColumns.push_back(c);
  // Output/Critical Mu Check: the uniqueness check after each converged step (a second instance
  // of the scene's solver, with determinants); the smallest mu_crit over the zones goes to
  // steps.csv.
  std::unique_ptr<LinearSolver> checkSolver;
  if (sm.criticalMuCheck && contact) {
    checkSolver = buildUniquenessCheckSolver(sm, comm);
    stepColumns.push_back("critical_mu");
  }
  int possiblyNonUnique = 0;
  // The linear solver's condition estimate of the last solve of each step, when it computes one
  // (mumps with Condition Estimate: true); its largest value goes to the summary.
  double maxCondition = -1;
  CsvWriter stepsCsv(stepColumns);
  RunProgress progress(root && !options.quiet, sm.solverOptions.endTime);
  auto x = system.createVector();

  // The displacement part of the system's unknowns (the whole vector without contact).
  auto displacementOf = [&](const Vector& solution) {
    return contact ? contact->displacement(solution)
                   : Teuchos::rcp(new Vector(solution, Teuchos::Copy));
  };
  CsvWriter contactCsv({"zone", "node", "x", "y", "z", "gap", "pressure", "traction_x",
                        "traction_y", "traction_z", "slip_x", "slip_y", "slip_z", "status"});
  auto writeContactCsv = [&] {
    CsvWriter table(contactCsv.columns());
    for (const auto& p : contact->results())
      table.addRow(sm.contact[p.zone].name, static_cast<long long>(p.node + 1), p.x[0], p.x[1],
                   p.x[2], p.paired ? p.gap : std::numeric_limits<double>::quiet_NaN(), p.pressure,
                   p.traction[0], p.traction[1], p.traction[2], p.slip[0], p.slip[1], p.slip[2],
                   outputStatus(p));
    table.write(outDir + "/contact.csv");
  };
  double lastPairing = 0, lastContact = 0;
  JsonValue probes = JsonValue::object();
  auto recordProbes = [&](const Vector& solution) {
    for (const auto& p : sm.probes) {
      JsonValue value = JsonValue::array();
      if (p.field == "displacement") {
        const auto d = problem->nodeDisplacement(solution, p.node);
        for (int c = 0; c < problem->dim(); ++c)
          value.push(d[c]);
      } else {
        for (double s : problem->nodeStress(solution, p.node))
          value.push(s);
      }
      const double* x = &sm.model.mesh->coords[3 * p.node];
      probes.set(
          p.name,
          JsonValue::object()
              .set("field", p.field)
              .set("point", JsonValue::array(std::vector<double>(p.point.begin(), p.point.end())))
              .set("node", JsonValue::array(std::vector<double>(x, x + 3)))
              .set("distance", p.distance)
              .set("value", value));
    }
  };
  auto contactSummary = [&](const ContactResultants& r) {
    auto vec = [&](const std::array<double, 3>& v) {
      return JsonValue::array(std::vector<double>(v.begin(), v.begin() + problem->dim()));
    };
    return JsonValue::object()
        .set("normal_force", r.normalForceMagnitude)
        .set("normal_force_vector", vec(r.normalForce))
        .set("tangential_force_vector", vec(r.tangentialForce))
        .set("max_pressure", r.maxPressure)
        .set("max_penetration", r.maxPenetration)
        .set("contact_points_closed", r.contact)
        .set("stick_points", r.stick)
        .set("slip_points", r.slip)
        .set("closed_frictionless_points", r.closedFrictionless)
        .set("surfaces_met", contact->everInContact());
  };
  // The contact block of the last converged step: after a failure, the contact state left in
  // the problem is the failed iterate's, which summary.json reports under a key of its own.
  JsonValue convergedContact;
  double lastTime = 0;
  auto onStep = [&](const StepReport& s, const Vector& state) {
    lastTime = s.time;
    auto solution = displacementOf(state);
    if (sm.writeVtk) {
      if (!vtk) vtk = std::make_unique<VtkSeriesWriter>(outDir, "result", mpiComm);
      MeshPiece piece = problem->outputPiece(*solution);
      if (contact) contact->addPointData(piece);
      vtk->writeStep(s.time, piece);
    }
    ContactResultants cr;
    double pairing = 0, contactTerms = 0;
    if (contact) {
      cr = contact->resultants();
      pairing = contact->pairingSeconds() - lastPairing;
      contactTerms = contact->contactSeconds() - lastContact;
      lastPairing = contact->pairingSeconds();
      lastContact = contact->contactSeconds();
      if (root) writeContactCsv();
      convergedContact = contactSummary(cr).set("time", s.time);
    }
    int events = 0;
    for (int k = 1; k < kCyclingKinds; ++k)
      events += s.cycling[k];
    using F = CsvWriter;
    std::vector<std::string> row{F::format(s.step),
                                 F::format(s.time),
                                 F::format(s.cuts),
                                 F::format(s.iterations),
                                 F::format(s.statusIterations),
                                 F::format(s.thresholdIterations),
                                 F::format(s.geometryIterations),
                                 F::format(s.iterations),
                                 F::format(s.residual),
                                 F::format(cr.contact),
                                 F::format(cr.stick),
                                 F::format(cr.slip),
                                 F::format(events)};
    for (int k = 1; k < kCyclingKinds; ++k)
      row.push_back(F::format(s.cycling[k]));
    const auto condition = solver->conditionEstimate();
    row.push_back(condition ? F::format(*condition) : std::string());
    if (condition) maxCondition = std::max(maxCondition, *condition);
    for (double v :
         {s.seconds.assembly - contactTerms, pairing, contactTerms, s.seconds.linearSolve})
      row.push_back(F::format(v));
    if (checkSolver) {
      std::string cell;
      try {
        const UniquenessCheck c = checkUniqueness(*contact, *contact, *checkSolver, state, s.time,
                                                  sm.criticalMuTolerance, sm.criticalMuMaxPatterns);
        double muCrit = std::numeric_limits<double>::infinity(), ratio = 0;
        for (const auto& zone : sm.contact)
          if (zone.friction > 0) {
            muCrit = std::min(muCrit, zone.friction * c.scale);
            ratio = std::max(ratio, 1.0 / c.scale);
          }
        cell = std::isinf(muCrit) ? "inf" : F::format(muCrit);
        if (ratio >= 1.0 || !c.sameSign) {
          ++possiblyNonUnique;
          if (root)
            std::cerr << "contactlab: warning: step " << s.step << " (t = " << s.time
                      << "): possibly non-unique: "
                      << (!c.sameSign ? "the Jacobians around the state differ in sign"
                                      : "mu >= mu_crit = " + F::format(muCrit))
                      << "\n";
        }
      } catch (const LinearSolverError& e) {
        cell = "singular";
        ++possiblyNonUnique;
        if (root)
          std::cerr << "contactlab: warning: step " << s.step << ": critical-mu check: " << e.what()
                    << "\n";
      }
      row.push_back(cell);
    }
    stepsCsv.addFormattedRow(std::move(row));
    if (root) stepsCsv.write(outDir + "/steps.csv");
    recordProbes(*solution);
    progress.step(s, steps, elapsed());
  };
  auto onIteration = [&](int step, double time, int it, double residual) {
    if (root) progress.iteration(step, time, it, residual, elapsed());
  };
  const RunReport report =
      runStatic(system, contact.get(), *solver, sm.solverOptions, *x, onStep, onIteration);
  // Said once per run: where the Dirichlet conditions fix a friction direction, its multiplier
  // was dropped (the singular tangent that would otherwise stop every algorithm there).
  if (contact)
    for (std::size_t z = 0; z < sm.contact.size(); ++z) {
      const std::vector<std::int64_t> nodes = contact->prescribedSlipNodes(z);
      if (root && !nodes.empty())
        std::cerr << "contactlab: Contact/" << sm.contact[z].name << ": at " << nodes.size()
                  << " slave node(s) (e.g. node " << nodes.front() + 1
                  << ") the Dirichlet conditions fix a friction direction: its friction "
                     "multiplier is dropped (the support carries that force)\n";
    }
  if (contact && root && report.steps > 0 && !contact->everInContact())
    std::cerr << "contactlab: warning: no contact point closed in any converged step: the "
                 "contact surfaces never met (check the geometry, the loads and the "
                 "search distance)\n";

  // Uniqueness: the critical friction coefficient of the last converged state's pattern.
  JsonValue criticalMu;
  if (options.criticalMu && !report.interruptSignal)
    criticalMu = criticalMuSummary(sm, contact.get(), *x, lastTime, report.steps, comm);

  // 3. Summary, also when the run failed (the last converged step stays written).
  const double localMemory = peakMemoryMB();
  double maxMemory = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 1, &localMemory, &maxMemory);
  const double pairingSeconds = contact ? contact->pairingSeconds() : 0.0;
  const double contactSeconds = contact ? contact->contactSeconds() : 0.0;
  long long contactMultipliers = 0, frictionMultipliers = 0;
  if (contact)
    for (const auto& p : contact->results())
      if (sm.contact[p.zone].law->hasMultipliers()) {
        ++contactMultipliers;
        frictionMultipliers += sm.contact[p.zone].friction > 0 ? problem->dim() - 1 : 0;
      }
  auto contactFormulations = [&] {
    if (!contact) return JsonValue();
    JsonValue zones = JsonValue::object();
    const auto& section = params.sublist("Contact");
    for (const auto& zone : sm.contact)
      zones.set(zone.name, typedSection(section.sublist(zone.name).sublist("Formulation"))
                               .set("friction", zone.friction)
                               .set("master", zone.obstacle ? "obstacle" : "surface"));
    return zones;
  };
  // Per zone: node-to-segment, or mortar with its multiplier basis.
  auto contactDiscretizations = [&] {
    if (!contact) return JsonValue();
    JsonValue zones = JsonValue::object();
    for (const auto& zone : sm.contact)
      zones.set(zone.name, zone.discretization == Discretization::nodeToSegment
                               ? std::string("node-to-segment")
                           : zone.multiplierBasis == MultiplierBasis::Dual
                               ? std::string("mortar (dual)")
                               : std::string("mortar (standard)"));
    return zones;
  };
  auto loop = [](bool inNewton) { return inNewton ? "newton" : "fixed-point"; };
  auto cyclingSummary = [&] {
    JsonValue counts = JsonValue::object();
    for (int k = 1; k < kCyclingKinds; ++k)
      counts.set(cyclingKindName(static_cast<CyclingKind>(k)), report.cycling[k]);
    return counts;
  };
  const MaterialStateSummary materialState = problem->materialState();  // collective
  if (root) {
    auto forces = [&](const std::vector<Reaction>& list) {
      JsonValue byName = JsonValue::object();
      for (const auto& r : list)
        byName.set(r.name, JsonValue::array(std::vector<double>(r.force.begin(),
                                                                r.force.begin() + problem->dim())));
      return byName;
    };
    JsonValue summary = JsonValue::object();
    summary.set("scene", sm.scene.name)
        .set("scene_file", sm.scene.path)
        .set("description", params.get<std::string>("Description"))
        .set("converged", report.converged)
        .set("failure", report.failure.empty() ? JsonValue() : JsonValue(report.failure))
        .set("message", report.message.empty() ? JsonValue() : JsonValue(report.message))
        .set("dimension", problem->dim())
        .set("mesh", typedSection(params.sublist("Mesh")))
        .set("formulation", contactFormulations())
        .set("discretization", contactDiscretizations())
        .set("algorithm",
             JsonValue::object()
                 .set("method", sm.solverOptions.method)
                 .set("geometry", loop(sm.solverOptions.geometryInNewton))
                 // Assembled only with the geometry in Newton (and contact).
                 .set("geometric_terms",
                      !contact || !sm.solverOptions.geometryInNewton               ? "none"
                      : sm.solverOptions.geometricTerms == GeometricTerms::full    ? "full"
                      : sm.solverOptions.geometricTerms == GeometricTerms::pairing ? "pairing"
                                                                                   : "none")
                 .set("friction_threshold", loop(sm.solverOptions.thresholdsInNewton))
                 .set("contact_statuses", loop(sm.solverOptions.statusesInNewton))
                 .set("cycling_treatment", sm.solverOptions.cyclingTreatment)
                 .set("regularization",
                      sm.solverOptions.slowDynamics.enabled ? "slow-dynamics" : "none")
                 .set("parameters", toJson(params.sublist("Algorithm")))
                 .set("newton", toJson(params.sublist("Newton"))))
        .set("linear_solver", typedSection(params.sublist("Linear Solver")))
        .set("dofs", static_cast<long long>(problem->dofs().numGlobalDofs()))
        .set("unknowns",
             JsonValue::object()
                 .set("displacement", static_cast<long long>(problem->dofs().numGlobalDofs()))
                 .set("contact_multipliers", contactMultipliers)
                 .set("friction_multipliers", frictionMultipliers))
        .set("nodes", static_cast<long long>(sm.model.mesh->numNodes()))
        .set("elements", static_cast<long long>(sm.model.mesh->numElements()))
        .set("contact_points", contact ? static_cast<long long>(contact->numPoints()) : 0LL)
        .set("ranks", comm->getSize())
        .set("load_steps", JsonValue::object()
                               .set("requested", steps)
                               .set("converged", report.steps)
                               .set("cuts", report.cuts))
        .set("iterations", JsonValue::object()
                               .set("newton", report.iterations)
                               .set("status", report.statusIterations)
                               .set("threshold", report.thresholdIterations)
                               .set("geometry", report.geometryIterations))
        .set("linear_solves", report.linearSolves)
        .set("condition_estimate", maxCondition >= 0 ? JsonValue(maxCondition) : JsonValue())
        .set("cycling", cyclingSummary())
        .set("seconds", JsonValue::object()
                            .set("setup", setupSeconds)
                            .set("assembly", report.seconds.assembly - contactSeconds)
                            .set("pairing", pairingSeconds)
                            .set("contact", contactSeconds)
                            .set("linear_solve", report.seconds.linearSolve)
                            .set("output", report.seconds.output)
                            .set("total", elapsed()))
        .set("peak_memory_mb", maxMemory)
        .set("contact", convergedContact)
        .set("failed_iterate",
             report.converged || !contact ? JsonValue() : contactSummary(contact->resultants()))
        .set("reactions", forces(problem->reactions()))
        // The force each spring exerts on the body (-sum k u).
        .set("springs", forces(problem->springForces()))
        .set("probes", probes)
        .set("result_pvd", vtk ? JsonValue(vtk->pvdPath()) : JsonValue());
    if (materialState.plasticity)
      summary.set("plasticity",
                  JsonValue::object()
                      .set("max_equivalent_plastic_strain", materialState.maxPlasticStrain)
                      .set("plastic_volume_fraction", materialState.plasticVolumeFraction));
    if (options.criticalMu) summary.set("critical_mu", criticalMu);
    if (checkSolver)
      summary.set("critical_mu_check", JsonValue::object()
                                           .set("steps_checked", report.steps)
                                           .set("possibly_non_unique", possiblyNonUnique));
    summary.write(outDir + "/summary.json");
    if (report.converged) {
      std::cout << "contactlab: " << sm.scene.name << " converged in " << report.steps
                << " step(s), " << report.iterations << " Newton iterations, " << elapsed()
                << " s\n";
    } else {
      std::cout << "contactlab: " << sm.scene.name << " FAILED (" << report.failure
                << "): " << report.message << "\n";
    }
    if (vtk)
      std::cout << "  results: " << std::filesystem::absolute(vtk->pvdPath()).string() << "\n";
    std::cout << "  summary: " << std::filesystem::absolute(outDir + "/summary.json").string()
              << "\n";
  }
  if (report.interruptSignal) return 128 + report.interruptSignal;
  return report.converged ? 0 : 1;
}

}  // namespace contactlab
