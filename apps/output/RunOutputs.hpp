#pragma once
// Everything a run writes into its output folder (doc/scenes.md "The output folder"), as one
// observer of the Simulation: the VTK series, steps.csv, contact.csv (and contact_t<time>.csv),
// the profiles, progress.log and the progress lines, the checkpoint, and at the end
// summary.json. Every file is listed first in the folder's manifest, which the next run there
// reads to remove this one's files, and nothing else.
#include "algorithms/StaticSolver.hpp"
#include "apps/Console.hpp"
#include "apps/RunCheckpoint.hpp"
#include "apps/RunProgress.hpp"
#include "apps/SceneModel.hpp"
#include "apps/output/ProbeValues.hpp"
#include "apps/output/ProfileCsv.hpp"
#include "apps/output/StepUniquenessCheck.hpp"
#include "apps/output/StepsCsv.hpp"
#include "apps/output/SummaryJson.hpp"
#include "apps/output/VtkSteps.hpp"
#include "core/io/OutputManifest.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace contactlab {

class LinearSolver;

// Where the series starts: a new folder, a state handed in (Initial State), or the same run
// continued (--restart) with what its checkpoint says was written.
struct OutputStart {
  bool restart = false;
  bool fromState = false;
  double time = 0;
  std::int64_t stepsRows = 0, vtkFrames = 0;
  int requestedSteps = 0;
  CheckpointInfo checkpoint;  // scene path, overrides and hash (the counts are filled per step)
};

class RunOutputs {
 public:
  // Collective. Writes the series' first frame (the rest frame, the state handed in), or
  // resumes a continued run's files. Throws InputError when the folder cannot be written.
  RunOutputs(const SceneModel& sm, Problem& problem, ContactProblem* contact,
             const LinearSolver& solver, const Teuchos::RCP<const Comm>& comm,
             const Console& console, const std::string& folder, const OutputStart& start,
             const Vector& x);
  ~RunOutputs();

  // Collective. After a converged step (`resultants`: its contact forces, zero without
  // contact): every per-step file, then the checkpoint.
  void step(const StepReport& s, const Vector& state, const ContactResultants& resultants,
            double elapsed);
  void iteration(const StaticSolver::IterateProgress& p, double elapsed) {
    if (root_) progress_.iteration(p, elapsed);
  }
  // After the run: what it did not reach (Output/Contact Times) and whether contact ever closed.
  void warnAfterRun(const RunReport& report) const;

  // The summary (the record's output fields filled in here); written by rank 0 with the closing
  // lines. materialState: Problem::materialState() (collective, so taken on every rank).
  JsonValue finish(const RunReport& report, RunRecord record,
                   const MaterialStateSummary& materialState, double elapsed);

  std::string path(const std::string& name) { return folder_.path(name); }

 private:
  const SceneModel& sm_;
  Problem& problem_;
  ContactProblem* contact_;
  const LinearSolver& solver_;
  Teuchos::RCP<const Comm> comm_;
  Console console_;
  bool root_;
  OutputManifest folder_;
  StepsCsv stepsCsv_;
  ProbeValues probes_;
  ProfileCsv profiles_;
  VtkSteps vtk_;
  SummaryJson summary_;
  std::unique_ptr<StepUniquenessCheck> uniqueness_;
  RunProgress progress_;
  int requestedSteps_;
  // The contact block of the last converged step: after a failure, the contact state left in
  // the problem is the failed iterate's, which summary.json reports under a key of its own.
  JsonValue convergedContact_;
  // The checkpoint's bookkeeping: what this output series holds before this run's steps.
  CheckpointInfo checkpoint_;
  std::int64_t earlierRows_;
  int stepsThisRun_ = 0;
  double startTime_;
  std::vector<double> contactTimesWritten_;
};

}  // namespace contactlab
