#include "apps/output/CriticalMuSummary.hpp"

#include "algorithms/PatternCriticalFriction.hpp"
#include "base/Elapsed.hpp"

#include <chrono>
#include <cmath>
#include <iostream>
#include <string>

namespace contactlab {

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
          .set("seconds", secondsSince(start))
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

}  // namespace contactlab
