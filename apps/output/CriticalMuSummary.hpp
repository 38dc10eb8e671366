#pragma once
// `contactlab critical-mu`, after the run: the uniqueness check of the last converged state
// (the status patterns around it, the signs of their Jacobians' determinants, the critical
// friction coefficient of each frictional zone) and its one verdict (uniquenessVerdict),
// printed through `console` (the details are info, mu_crit and the verdict the command's
// result) and returned for summary.json (critical_mu). The solver is a second instance of the
// scene's, with determinants.
#include "apps/Console.hpp"
#include "apps/SceneModel.hpp"
#include "core/io/JsonWriter.hpp"
#include "formulations/ContactProblem.hpp"

namespace contactlab {

// Collective. x: the converged state at time t; contact may be null. When there is nothing to
// check (no contact, no friction, no converged step) says why, and returns
// {"computed": false, "reason": ...}.
JsonValue criticalMuSummary(const SceneModel& sm, ContactProblem* contact, const Vector& x,
                            double t, int convergedSteps, const Teuchos::RCP<const Comm>& comm,
                            const Console& console);

}  // namespace contactlab
