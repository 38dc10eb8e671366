#include "apps/output/CriticalMuSummary.hpp"

#include "algorithms/PatternCriticalFriction.hpp"
#include "algorithms/UniquenessVerdict.hpp"
#include "base/Elapsed.hpp"
#include "base/NumberText.hpp"

#include <chrono>
#include <cmath>
#include <string>

namespace contactlab {

JsonValue criticalMuSummary(const SceneModel& sm, ContactProblem* contact, const Vector& x,
                            double t, int convergedSteps, const Teuchos::RCP<const Comm>& comm,
                            const Console& console) {
  std::string why;
  if (!contact)
    why = "the scene has no contact";
  else if (!hasFriction(sm))
    why = "no contact zone has friction (mu = 0)";
  else if (convergedSteps == 0)
    why = "no load step converged";
  if (!why.empty()) {
    console.result("contactlab: critical-mu: not computed: " + why);
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
  const UniquenessVerdict verdict = uniquenessVerdict(c);
  const auto factor = [](double s) { return std::isinf(s) ? std::string("none") : numberText(s); };
  console.info("critical-mu: converged state at t = " + numberText(t) + ": " +
               std::to_string(c.ambiguousPoints) + " ambiguous point(s), " +
               std::to_string(c.patterns) + " status pattern(s) examined (" + c.choice + "; " +
               std::to_string(c.updatedPatterns) +
               " by updates of the converged pattern's factorization)");
  console.info("critical-mu: critical factor on mu of the adjacent patterns " +
               factor(c.localScale) + ", of the contact set slipping " + factor(c.slipScale));
  if (std::isinf(c.scale)) {
    console.result(
        "contactlab: critical-mu: no critical mu (det J(s mu) has no positive real "
        "root on these patterns)");
  } else {
    std::string line = "contactlab: critical-mu: critical factor " + numberText(c.scale) + " on mu";
    for (const auto& zone : sm.contact)
      if (zone.friction > 0)
        line += "; " + zone.name + ": mu = " + numberText(zone.friction) +
                ", mu_crit = " + numberText(zone.friction * c.scale);
    console.result(line);
  }
  console.result("contactlab: critical-mu: " + verdict.verdict + ": " + verdict.reason);
  JsonValue out =
      JsonValue::object()
          .set("computed", true)
          .set("time", t)
          .set("seconds", secondsSince(start))
          .set("friction_rows", c.frictionRows)
          .set("ambiguous_points", c.ambiguousPoints)
          .set("patterns_examined", c.patterns)
          .set("patterns_updated", c.updatedPatterns)
          .set("pattern_choice", c.choice)
          .set("verdict", verdict.verdict)
          .set("verdict_reason", verdict.reason)
          .set("singular_patterns", c.singularPatterns)
          .set("breaking_pattern",
               c.breakingPattern.empty() ? JsonValue() : JsonValue(c.breakingPattern))
          .set("factor", std::isinf(c.scale) ? JsonValue() : JsonValue(c.scale))
          .set("adjacent_factor", std::isinf(c.localScale) ? JsonValue() : JsonValue(c.localScale))
          .set("slipping_factor", std::isinf(c.slipScale) ? JsonValue() : JsonValue(c.slipScale))
          .set("zones", zones);
  return out;
}

}  // namespace contactlab
