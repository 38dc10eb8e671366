#pragma once
// steps.csv (doc/scenes.md "The output folder"): one row per converged load step with the
// iterations of each loop, the residual, the contact/stick/slip counts, the contact force on the
// slave surfaces (sum w p and the vector sum w (p n + t): a force history), the cycling events by
// kind, the linear solver's condition estimate, the seconds per phase and, with Output/Critical Mu
// Check, that step's critical mu. Rewritten whole after each step (atomically, by rank 0), so a
// crash leaves the rows of every converged step.
#include "algorithms/StaticSolver.hpp"
#include "core/io/CsvWriter.hpp"
#include "core/io/OutputManifest.hpp"
#include "formulations/ContactProblem.hpp"

#include <optional>
#include <string>

namespace contactlab {

class StepsCsv {
 public:
  static constexpr const char* kFileName = "steps.csv";

  // criticalMuColumn: the run checks uniqueness after each step (Output/Critical Mu Check).
  // The file is `folder`'s steps.csv, listed in its manifest when first written.
  StepsCsv(OutputManifest& folder, bool criticalMuColumn);

  // One converged step. contactSeconds: the contact problem's timers since the start (none
  // without contact); the row gets this step's share of each, and assembly_s is the solid's
  // share (without contact: the step's assembly seconds).
  // criticalMu: the cell of the critical mu column (given exactly when it exists).
  void addStep(const StepReport& step, const ContactResultants& resultants,
               std::optional<double> conditionEstimate,
               const std::optional<ContactPhaseSeconds>& contactSeconds,
               const std::optional<std::string>& criticalMu);

  // A run continued from a checkpoint (--restart): the file's first `rows` rows (those of the
  // steps up to the checkpoint) come before the new ones. Call on rank 0 only, before write().
  // Throws std::runtime_error when the file has fewer rows.
  void resume(std::int64_t rows);

  // Writes the file; call on rank 0 only.
  void write();

  // The largest condition estimate of the rows, < 0 when the solver gave none.
  double maxConditionEstimate() const { return maxCondition_; }

 private:
  OutputManifest& folder_;
  CsvWriter table_;
  std::string earlierRows_;   // resume(): the earlier run's rows, as written
  ContactPhaseSeconds last_;  // the contact problem's timers at the previous row
  double maxCondition_ = -1;
};

}  // namespace contactlab
