#pragma once
// The checkpoint of a run: checkpoint.h5 in its output folder, replaced (atomically) after each
// converged step. It holds everything the next step starts from, so that a new run can start
// from it (the scene's `Initial State: {From: DIR}`) and a killed run can be continued
// (`contactlab run --restart DIR`, Simulation): the load time, step number and next step size,
// the displacements by mesh node id, the contact point unknowns and friction history
// (ContactProblem::convergedHistory), the internal variables of every element by element id
// (Problem::gatherElementStates), and what --restart needs to append to the output series. HDF5
// (core/io/Hdf5Writer): a user reads it with h5dump or h5py; the layout is in doc/scenes.md
// "Checkpoints". Gathered to rank 0, so the file does not depend on the number of ranks.
#include "algorithms/StepReport.hpp"
#include "base/LinearAlgebra.hpp"

#include <Teuchos_ParameterList.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace contactlab {

class ContactProblem;
class Problem;

// What a checkpoint says besides the state.
struct CheckpointInfo {
  // The scene it was run from: its path and --set overrides (--restart reads the scene again),
  // and the hash of its validated parameters (sceneHash) that --restart compares.
  std::string scenePath;
  std::vector<std::string> overrides;
  std::string sceneHash;
  double time = 0;           // load time of the last converged step
  int step = 0;              // its number
  double stepSize = 0;       // the increment the next step tries (after cuts, smaller than nominal)
  double loadReference = 0;  // StepReport::loadReference (0 in checkpoints written before it)
  // The output series so far (--restart keeps exactly these): rows of steps.csv, frames of
  // result.pvd.
  std::int64_t stepsRows = 0, vtkFrames = 0;
  // Run totals so far (summary.json of a continued run counts the whole run).
  RunTotals totals;
};

// The file in a run's output folder.
constexpr const char* kCheckpointFile = "checkpoint.h5";
std::string checkpointPath(const std::string& folder);

// A hash of the validated scene (every value, defaults included; comments and layout do not
// count): --restart refuses a scene whose hash changed.
std::string sceneHash(const Teuchos::ParameterList& scene);

// Collective: gathers the converged state x (after commitState) on rank 0, which writes `path`.
void writeCheckpoint(const std::string& path, const CheckpointInfo& info, const Problem& problem,
                     ContactProblem* contact, const Vector& x, const StepContinuation& last = {});

// Reads what a checkpoint says besides the state (any rank). Throws InputError for a missing or
// unreadable file.
CheckpointInfo readCheckpointInfo(const std::string& path);

// Collective: every rank reads `path` and takes its part of the state into x (the system's
// unknowns), the problem's elements and the contact points. Throws InputError, the same on every
// rank, when the file is missing or unreadable or its mesh, elements or contact points are not
// this model's. continueTime false: the contact history's converged time is 0 (Initial State
// Time: zero), else the checkpoint's. `last`, when given, receives the checkpoint's last step's
// StepContinuation (null vectors where it has none).
CheckpointInfo restoreCheckpoint(const std::string& path, Problem& problem, ContactProblem* contact,
                                 Vector& x, bool continueTime = true,
                                 StepContinuation* last = nullptr);

}  // namespace contactlab
