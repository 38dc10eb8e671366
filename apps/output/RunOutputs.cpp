#include "apps/output/RunOutputs.hpp"

#include "apps/output/ContactCsv.hpp"
#include "base/InputError.hpp"
#include "base/NumberText.hpp"
#include "core/io/OutputFolder.hpp"
#include "core/problem/CollectiveError.hpp"
#include "core/problem/Problem.hpp"
#include "formulations/ContactProblem.hpp"
#include "linear/LinearSolver.hpp"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace contactlab {
namespace {

// For the tests of restarts: CONTACTLAB_TEST_KILL_AFTER_STEP=k kills every rank with SIGKILL
// right after step k's outputs and checkpoint are written (a crash at a step boundary, which
// nothing can clean up after).
void killAfterStepForTests(int step, const Comm& comm) {
  const char* value = std::getenv("CONTACTLAB_TEST_KILL_AFTER_STEP");
  if (value == nullptr || std::atoi(value) != step) return;
  comm.barrier();
  std::raise(SIGKILL);
}

}  // namespace

RunOutputs::RunOutputs(const SceneModel& sm, Problem& problem, ContactProblem* contact,
                       const LinearSolver& solver, const Teuchos::RCP<const Comm>& comm,
                       const Console& console, const std::string& folder, const OutputStart& start,
                       const Vector& x)
    : sm_(sm),
      problem_(problem),
      contact_(contact),
      solver_(solver),
      comm_(comm),
      console_(console),
      root_(comm->getRank() == 0),
      folder_(folder, root_),
      stepsCsv_(folder_, sm.criticalMuCheck && contact),
      probes_(sm, problem),
      profiles_(sm, problem),
      vtk_(folder_, rawMpiComm(comm)),
      summary_(sm, problem, contact),
      progress_(root_ && !console.quiet(), sm.solverOptions.endTime,
                root_ ? folder_.path("progress.log") : "", start.restart),
      requestedSteps_(start.requestedSteps),
      checkpoint_(start.checkpoint),
      earlierRows_(start.restart ? start.stepsRows : 0),
      startTime_(start.time) {
  // The series starts from rest: a t = 0 frame before step 1 (also what a run that converges
  // no step leaves); a run from an earlier state starts from that state, at its time; a
  // continued run appends to its series.
  if (start.restart) {
    // Continued: the series keep what was written up to the checkpoint, the rest is dropped.
    collectively(*comm_, [&] {
      if (!root_) return;
      prepareContinuedFolder(folder);
      stepsCsv_.resume(start.stepsRows);
    });
    if (sm.writeVtk) collectively(*comm_, [&] { vtk_.resume(static_cast<int>(start.vtkFrames)); });
  } else if (sm.writeVtk && start.fromState) {
    vtk_.write(start.time, problem, contact, contact ? *contact->displacement(x) : x);
  } else if (sm.writeVtk) {
    vtk_.writeRest(problem, contact);
  }
  // Output/Critical Mu Check: the uniqueness check after each converged step.
  if (sm.criticalMuCheck && contact)
    uniqueness_ = std::make_unique<StepUniquenessCheck>(sm, *contact, comm, console);
}

RunOutputs::~RunOutputs() = default;

void RunOutputs::step(const StepReport& s, const Vector& state, const ContactResultants& cr,
                      double elapsed) {
  // The displacement part of the system's unknowns (the whole vector without contact).
  auto solution =
      contact_ ? contact_->displacement(state) : Teuchos::rcp(new Vector(state, Teuchos::Copy));
  if (sm_.writeVtk) vtk_.write(s.time, problem_, contact_, *solution);
  // The Output/Contact Times entry this step lands on, if any: its outputs are kept under the
  // time's name too.
  std::optional<double> stage;
  for (double t : sm_.contactTimes)
    if (std::abs(s.time - t) <= 1e-9 * sm_.solverOptions.endTime) stage = t;
  if (contact_) {
    if (root_)
      ContactCsv(folder_.path("contact.csv")).write(*contact_, sm_.contact, *sm_.model.mesh);
    if (stage) {
      if (root_)
        ContactCsv(folder_.path("contact_t" + numberText(*stage) + ".csv"))
            .write(*contact_, sm_.contact, *sm_.model.mesh);
      contactTimesWritten_.push_back(*stage);
    }
    convergedContact_ = summary_.contactBlock(cr).set("time", s.time);
  }
  // Read before the uniqueness check, whose assemblies count in the next step's timings.
  std::optional<ContactPhaseSeconds> contactSeconds;
  if (contact_) contactSeconds = contact_->phaseSeconds();
  const std::optional<double> condition = solver_.conditionEstimate();
  std::optional<std::string> criticalMu;
  if (uniqueness_) criticalMu = uniqueness_->check(s, state);
  stepsCsv_.addStep(s, cr, condition, contactSeconds, criticalMu);
  if (root_) stepsCsv_.write();
  probes_.record(*solution, s.time);
  if (!sm_.profiles.empty()) {
    profiles_.write(folder_, "", *solution, s.time);
    if (stage) profiles_.write(folder_, "_t" + numberText(*stage), *solution, s.time);
  }
  progress_.step(s, requestedSteps_, elapsed);
  // The checkpoint last: when it names a step, that step's outputs are all written.
  ++stepsThisRun_;
  checkpoint_.time = s.time;
  checkpoint_.step = s.step;
  checkpoint_.stepSize = s.nextStepSize;
  checkpoint_.loadReference = s.loadReference;
  checkpoint_.stepsRows = earlierRows_ + stepsThisRun_;
  checkpoint_.vtkFrames = vtk_.frames();
  checkpoint_.totals = s.run;
  const bool last = s.time >= sm_.solverOptions.endTime;
  if (sm_.checkpointEvery > 0 && (s.step % sm_.checkpointEvery == 0 || last))
    writeCheckpoint(folder_.path(kCheckpointFile), checkpoint_, problem_, contact_, state,
                    s.continuation);
  killAfterStepForTests(s.step, *comm_);
}

void RunOutputs::warnAfterRun(const RunReport& report) const {
  if (!contact_ || !report.converged) return;
  // Output/Contact Times this run reached no converged step at (a continued run's earlier part
  // wrote its own).
  for (double t : sm_.contactTimes)
    if (t > startTime_ && std::find(contactTimesWritten_.begin(), contactTimesWritten_.end(), t) ==
                              contactTimesWritten_.end())
      console_.warning("Output/Contact Times: no converged step at t = " + numberText(t) +
                       ": contact_t" + numberText(t) + ".csv was not written");
  // Only for a run that reached its end: a failed one may have failed where the surfaces met
  // (the seed-size tube under generalized Newton, at the joint's closing), and the warning
  // would send its user to check a geometry that is right.
  if (report.steps > 0 && !contact_->everInContact())
    console_.warning(
        "no contact point closed in any converged step: the contact surfaces never met (check "
        "the geometry, the loads and the search distance)");
}

JsonValue RunOutputs::finish(const RunReport& report, RunRecord record,
                             const MaterialStateSummary& materialState, double elapsed) {
  if (!root_) return {};
  record.maxCondition = stepsCsv_.maxConditionEstimate();
  record.convergedContact = convergedContact_;
  record.probes = probes_.json();
  record.resultPvd = vtk_.pvdPath();
  if (uniqueness_) record.possiblyNonUnique = uniqueness_->possiblyNonUnique();
  record.totalSeconds = elapsed;
  const LinearSolverStats& work = solver_.stats();
  record.linearWork =
      JsonValue::object()
          .set("analyses", work.analyses)
          .set("analysis_seconds", work.analysisSeconds)
          .set("factorizations", work.factorizations)
          .set("reused_factorizations", work.reusedFactorizations)
          .set("corrections", work.corrections)
          .set("single_precision_factorizations", work.singlePrecisionFactorizations)
          .set("refinement_steps", work.refinementSteps)
          .set("double_precision_fallbacks", work.doublePrecisionFallbacks)
          .set("factorization_seconds", work.factorizationSeconds)
          .set("correction_seconds", work.correctionSeconds)
          .set("solve_seconds", work.solveSeconds);
  JsonValue summary = summary_.build(report, record, materialState, comm_->getSize());
  summary.write(folder_.path("summary.json"));
  std::ostringstream closing;
  if (report.converged)
    closing << "contactlab: " << sm_.scene.name << " converged in " << report.steps << " step(s), "
            << report.iterations << " Newton iterations, " << elapsed << " s";
  else
    closing << "contactlab: " << sm_.scene.name << " FAILED (" << report.failure
            << "): " << report.message;
  console_.result(closing.str());
  progress_.finish(closing.str());
  if (record.resultPvd)
    console_.result("  results: " + std::filesystem::absolute(*record.resultPvd).string());
  console_.result("  summary: " +
                  std::filesystem::absolute(folder_.folder() + "/summary.json").string());
  return summary;
}

}  // namespace contactlab
