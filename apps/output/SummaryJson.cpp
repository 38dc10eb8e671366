#include "apps/output/SummaryJson.hpp"

#include "formulations/ContactDiscretizationType.hpp"

#include <Teuchos_ParameterList.hpp>

#include <cctype>
#include <vector>

namespace contactlab {
namespace {

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

const char* loop(bool inNewton) {
  return inNewton ? "newton" : "fixed-point";
}

// "Normal Augmentation" -> "normal_augmentation".
std::string snakeCase(const std::string& key) {
  std::string out;
  for (char c : key)
    out += c == ' ' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

JsonValue orNull(const std::string& text) {
  return text.empty() ? JsonValue() : JsonValue(text);
}

}  // namespace

SummaryJson::SummaryJson(const SceneModel& sm, const Problem& problem,
                         const ContactProblem* contact)
    : sm_(sm), problem_(problem), contact_(contact) {}

JsonValue SummaryJson::contactBlock(const ContactResultants& r) const {
  auto vec = [&](const std::array<double, 3>& v) {
    return JsonValue::array(std::vector<double>(v.begin(), v.begin() + problem_.dim()));
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
      .set("surfaces_met", contact_->everInContact());
}

// Per block: the element technology used, what the scene asked for and automatic's reason.
JsonValue SummaryJson::elementTechnologies() const {
  JsonValue blocks = JsonValue::object();
  for (const BlockTechnology& t : problem_.elementTechnologies()) {
    JsonValue block = JsonValue::object().set("technology", t.name).set("requested", t.requested);
    if (!t.reason.empty()) block.set("reason", t.reason);
    blocks.set(t.block, block);
  }
  return blocks;
}

// Per zone: its formulation with parameters, friction, and whether the master is an obstacle.
JsonValue SummaryJson::formulations() const {
  if (!contact_) return JsonValue();
  JsonValue zones = JsonValue::object();
  const auto& section = sm_.scene.params->sublist("Contact");
  for (const auto& zone : sm_.contact) {
    JsonValue formulation = typedSection(section.sublist(zone.name).sublist("Formulation"))
                                .set("friction", zone.friction)
                                .set("master", zone.obstacle ? "obstacle" : "surface");
    // The coefficients a scene left at 0 (its parameters above say 0): automatic_<key>.
    const auto automatic = sm_.automaticCoefficients.find(zone.name);
    if (automatic != sm_.automaticCoefficients.end())
      for (const auto& [key, value] : automatic->second)
        formulation.set("automatic_" + snakeCase(key), value);
    zones.set(zone.name, formulation);
  }
  return zones;
}

// Per zone: its discretization, with the multiplier basis where it has one.
JsonValue SummaryJson::discretizations() const {
  if (!contact_) return JsonValue();
  JsonValue zones = JsonValue::object();
  for (const auto& zone : sm_.contact)
    zones.set(zone.name, contactDiscretizationType(zone.discretization).label(zone));
  return zones;
}

JsonValue SummaryJson::algorithm() const {
  const StaticSolverOptions& o = sm_.solverOptions;
  const auto& params = *sm_.scene.params;
  return JsonValue::object()
      .set("method", o.method)
      .set("geometry", loop(o.geometryInNewton))
      // Assembled only with the geometry in Newton (and contact).
      .set("geometric_terms", !contact_ || !o.geometryInNewton              ? "none"
                              : o.geometricTerms == GeometricTerms::full    ? "full"
                              : o.geometricTerms == GeometricTerms::pairing ? "pairing"
                                                                            : "none")
      .set("friction_threshold", loop(o.thresholdsInNewton))
      .set("contact_statuses", loop(o.statusesInNewton))
      .set("cycling_treatment", o.cyclingTreatment)
      .set("regularization", o.slowDynamics.enabled ? "slow-dynamics" : "none")
      .set("parameters", toJson(params.sublist("Algorithm")))
      .set("newton", toJson(params.sublist("Newton")));
}

// Displacement dofs, the multipliers of the points that have them (one normal, and d - 1
// friction ones with friction), and the normal-field formulation's slave normals (d each).
JsonValue SummaryJson::unknowns() const {
  long long contactMultipliers = 0, frictionMultipliers = 0, normalField = 0;
  if (contact_)
    for (const auto& p : contact_->results()) {
      const ContactLaw& law = *sm_.contact[p.zone].law;
      if (law.hasMultipliers()) {
        ++contactMultipliers;
        frictionMultipliers += sm_.contact[p.zone].friction > 0 ? problem_.dim() - 1 : 0;
      }
      if (law.hasNormalField()) normalField += problem_.dim();
    }
  return JsonValue::object()
      .set("displacement", static_cast<long long>(problem_.dofs().numGlobalDofs()))
      .set("contact_multipliers", contactMultipliers)
      .set("friction_multipliers", frictionMultipliers)
      .set("normal_field", normalField);
}

JsonValue SummaryJson::forces(const std::vector<Reaction>& list) const {
  JsonValue byName = JsonValue::object();
  for (const auto& r : list)
    byName.set(r.name, JsonValue::array(
                           std::vector<double>(r.force.begin(), r.force.begin() + problem_.dim())));
  return byName;
}

JsonValue SummaryJson::build(const RunReport& report, const RunRecord& record,
                             const MaterialStateSummary& materialState, int ranks) const {
  const auto& params = *sm_.scene.params;
  const ContactPhaseSeconds contactSeconds =
      contact_ ? contact_->phaseSeconds() : ContactPhaseSeconds{0, report.seconds.assembly, 0};
  JsonValue cycling = JsonValue::object();
  for (int k = 1; k < kCyclingKinds; ++k)
    cycling.set(cyclingKindName(static_cast<CyclingKind>(k)), report.cycling[k]);
  JsonValue summary = JsonValue::object();
  summary.set("scene", sm_.scene.name)
      .set("scene_file", sm_.scene.path)
      .set("description", params.get<std::string>("Description"))
      .set("converged", report.converged)
      .set("failure", orNull(report.failure))
      .set("message", orNull(report.message))
      .set("dimension", problem_.dim())
      .set("mesh", typedSection(params.sublist("Mesh")))
      .set("element_technology", elementTechnologies())
      .set("formulation", formulations())
      .set("discretization", discretizations())
      .set("algorithm", algorithm())
      .set("linear_solver", typedSection(params.sublist("Linear Solver")))
      .set("dofs", static_cast<long long>(problem_.dofs().numGlobalDofs()))
      .set("unknowns", unknowns())
      .set("nodes", static_cast<long long>(sm_.model.mesh->numNodes()))
      .set("elements", static_cast<long long>(sm_.model.mesh->numElements()))
      .set("contact_points", contact_ ? static_cast<long long>(contact_->numPoints()) : 0LL)
      .set("ranks", ranks)
      .set("load_steps", JsonValue::object()
                             .set("requested", sm_.solverOptions.requestedSteps())
                             .set("converged", report.steps)
                             .set("cuts", report.cuts)
                             .set("line_search_retries", report.lineSearchRetries)
                             .set("geometry_retries", report.geometryRetries))
      .set("limited_updates", report.limitedUpdates)
      .set("unevaluable_halvings", report.unevaluableHalvings)
      .set("roundoff_stops", report.roundoffStops)
      .set("iterations", JsonValue::object()
                             .set("newton", report.iterations)
                             .set("status", report.statusIterations)
                             .set("threshold", report.thresholdIterations)
                             .set("geometry", report.geometryIterations))
      .set("linear_solves", report.linearSolves)
      .set("linear_work", record.linearWork)
      .set("condition_estimate",
           record.maxCondition >= 0 ? JsonValue(record.maxCondition) : JsonValue())
      .set("cycling", cycling)
      .set("seconds", JsonValue::object()
                          .set("setup", record.setupSeconds)
                          .set("assembly", contactSeconds.solid)
                          .set("pairing", contactSeconds.pairing)
                          .set("contact", contactSeconds.contact)
                          .set("linear_solve", report.seconds.linearSolve)
                          .set("output", report.seconds.output)
                          .set("total", record.totalSeconds))
      .set("peak_memory_mb", record.peakMemoryMB)
      .set("contact", record.convergedContact)
      .set("failed_iterate",
           report.converged || !contact_ ? JsonValue() : contactBlock(contact_->resultants()))
      .set("reactions", forces(problem_.reactions()))
      // The force each spring exerts on the body (-sum k u).
      .set("springs", forces(problem_.springForces()))
      .set("probes", record.probes)
      .set("result_pvd", record.resultPvd ? JsonValue(*record.resultPvd) : JsonValue());
  if (materialState.plasticity)
    summary.set("plasticity",
                JsonValue::object()
                    .set("max_equivalent_plastic_strain", materialState.maxPlasticStrain)
                    .set("plastic_volume_fraction", materialState.plasticVolumeFraction));
  if (record.criticalMu) summary.set("critical_mu", *record.criticalMu);
  if (record.possiblyNonUnique)
    summary.set("critical_mu_check", JsonValue::object()
                                         .set("steps_checked", report.steps)
                                         .set("possibly_non_unique", *record.possiblyNonUnique));
  return summary;
}

}  // namespace contactlab
