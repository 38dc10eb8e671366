#pragma once
// summary.json (doc/scenes.md "The output folder"), written once at the end of a run, also a failed
// one: the scene, whether and why it failed, each axis with its parameters, sizes, iteration totals
// per loop, cycling counts, seconds per phase, peak memory, contact resultants, reactions, spring
// forces, probes, and the uniqueness checks when they ran.
#include "algorithms/StaticSolver.hpp"
#include "apps/SceneModel.hpp"
#include "core/io/JsonWriter.hpp"
#include "core/problem/Problem.hpp"
#include "formulations/ContactProblem.hpp"

#include <optional>
#include <string>

namespace contactlab {

// What the run gathered besides its report, for the summary.
struct RunRecord {
  double setupSeconds = 0;
  double totalSeconds = 0;
  double peakMemoryMB = 0;     // the largest over the ranks
  double maxCondition = -1;    // the linear solver's largest condition estimate; < 0: none
  JsonValue convergedContact;  // contactBlock of the last converged step; null: none
  JsonValue probes;            // ProbeValues::json()
  std::optional<std::string> resultPvd;
  std::optional<JsonValue> criticalMu;   // `contactlab critical-mu` only
  std::optional<int> possiblyNonUnique;  // Output/Critical Mu Check only
  JsonValue linearWork;                  // the linear solver's counts (factorizations, ...)
};

class SummaryJson {
 public:
  // contact may be null (a scene without contact).
  SummaryJson(const SceneModel& sm, const Problem& problem, const ContactProblem* contact);

  // The contact block of a contact state (the last converged step, or the failed iterate).
  JsonValue contactBlock(const ContactResultants& resultants) const;

  // The whole summary. materialState: Problem::materialState(), which is collective, so the
  // caller takes it on every rank; the rest is local (call it on rank 0).
  JsonValue build(const RunReport& report, const RunRecord& record,
                  const MaterialStateSummary& materialState, int ranks) const;

 private:
  JsonValue elementTechnologies() const;
  JsonValue formulations() const;
  JsonValue discretizations() const;
  JsonValue algorithm() const;
  JsonValue unknowns() const;
  JsonValue forces(const std::vector<Reaction>& list) const;

  const SceneModel& sm_;
  const Problem& problem_;
  const ContactProblem* contact_;
};

}  // namespace contactlab
