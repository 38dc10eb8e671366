#include "apps/output/StepUniquenessCheck.hpp"

#include "algorithms/PatternCriticalFriction.hpp"
#include "algorithms/UniquenessVerdict.hpp"
#include "base/NumberText.hpp"
#include "core/io/CsvWriter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace contactlab {

StepUniquenessCheck::StepUniquenessCheck(const SceneModel& sm, ContactProblem& contact,
                                         const Teuchos::RCP<const Comm>& comm,
                                         const Console& console)
    : sm_(sm),
      contact_(contact),
      console_(console),
      solver_(buildUniquenessCheckSolver(sm, comm)) {}

std::string StepUniquenessCheck::check(const StepReport& s, const Vector& state) {
  using F = CsvWriter;
  std::string cell;
  const std::string step = "step " + std::to_string(s.step) + " (t = " + numberText(s.time) + ")";
  try {
    const UniquenessCheck c = checkUniqueness(contact_, contact_, *solver_, state, s.time,
                                              sm_.criticalMuTolerance, sm_.criticalMuMaxPatterns);
    double muCrit = std::numeric_limits<double>::infinity();
    for (const auto& zone : sm_.contact)
      if (zone.friction > 0) muCrit = std::min(muCrit, zone.friction * c.scale);
    cell = std::isinf(muCrit) ? "inf" : F::format(muCrit);
    const UniquenessVerdict verdict = uniquenessVerdict(c);
    if (verdict.possiblyNonUnique) {
      ++possiblyNonUnique_;
      console_.warning(step + ": " + verdict.verdict + ": " + verdict.reason);
    }
  } catch (const LinearSolverError& e) {
    cell = "singular";
    ++possiblyNonUnique_;
    console_.warning(step + ": critical-mu check: " + e.what());
  }
  return cell;
}

}  // namespace contactlab
