#include "apps/output/StepUniquenessCheck.hpp"

#include "algorithms/PatternCriticalFriction.hpp"
#include "core/io/CsvWriter.hpp"

#include <cmath>
#include <iostream>
#include <limits>

namespace contactlab {

StepUniquenessCheck::StepUniquenessCheck(const SceneModel& sm, ContactProblem& contact,
                                         const Teuchos::RCP<const Comm>& comm)
    : sm_(sm),
      contact_(contact),
      root_(comm->getRank() == 0),
      solver_(buildUniquenessCheckSolver(sm, comm)) {}

std::string StepUniquenessCheck::check(const StepReport& s, const Vector& state) {
  using F = CsvWriter;
  std::string cell;
  try {
    const UniquenessCheck c = checkUniqueness(contact_, contact_, *solver_, state, s.time,
                                              sm_.criticalMuTolerance, sm_.criticalMuMaxPatterns);
    double muCrit = std::numeric_limits<double>::infinity(), ratio = 0;
    for (const auto& zone : sm_.contact)
      if (zone.friction > 0) {
        muCrit = std::min(muCrit, zone.friction * c.scale);
        ratio = std::max(ratio, 1.0 / c.scale);
      }
    cell = std::isinf(muCrit) ? "inf" : F::format(muCrit);
    if (ratio >= 1.0 || !c.sameSign) {
      ++possiblyNonUnique_;
      if (root_)
        std::cerr << "contactlab: warning: step " << s.step << " (t = " << s.time
                  << "): possibly non-unique: "
                  << (!c.sameSign ? "the Jacobians around the state differ in sign"
                                  : "mu >= mu_crit = " + F::format(muCrit))
                  << "\n";
    }
  } catch (const LinearSolverError& e) {
    cell = "singular";
    ++possiblyNonUnique_;
    if (root_)
      std::cerr << "contactlab: warning: step " << s.step << ": critical-mu check: " << e.what()
                << "\n";
  }
  return cell;
}

}  // namespace contactlab
