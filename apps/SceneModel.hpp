#pragma once
// A validated scene turned into the objects that run it: the mesh (built on rank 0 and
// broadcast), the solid model, the solver options and the probes.
#include "algorithms/StaticSolver.hpp"
#include "core/io/SceneFile.hpp"
#include "core/problem/SolidModel.hpp"
#include "formulations/ContactZone.hpp"
#include "linear/LinearSolver.hpp"

#include <Teuchos_ParameterList.hpp>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace contactlab {

class MeshCache;

struct Probe {
  std::string name;
  std::string field;  // "displacement" or "stress"
  std::array<double, 3> point{};
  std::int64_t node = -1;  // closest mesh node
  double distance = 0;
};

// Output/Profiles/<name>: a field along a segment, read at the mesh nodes nearest `points`
// evenly spaced points from `from` to `to` (profile_<name>.csv).
struct Profile {
  std::string name;
  std::string field;  // "displacement" or "stress"
  std::string frame;  // "cartesian" or "cylindrical" (about `axis` through `centre`)
  std::array<double, 3> from{}, to{}, centre{}, axis{{0, 0, 1}};
  std::vector<std::array<double, 3>> points;
  std::vector<std::int64_t> nodes;  // nearest mesh node of each point
  std::vector<double> distances;
};

struct SceneModel {
  SceneFile scene;  // validated, defaults filled in
  SolidModel model;
  std::vector<ContactZone> contact;  // empty: no contact (no contact unknowns are built)
  StaticSolverOptions solverOptions;
  std::vector<Probe> probes;
  std::vector<Profile> profiles;
  std::string outputDirectory;
  // Initial State: the folder whose checkpoint the run starts from (empty: from rest), and
  // whether the load time continues from the checkpoint's (Time: continue) or restarts at 0.
  std::string initialStateFrom;
  bool initialStateContinuesTime = true;
  int checkpointEvery = 1;           // Output/Checkpoint Every (0: no checkpoint)
  std::vector<double> contactTimes;  // Output/Contact Times: contact_t<time>.csv at each
  bool writeVtk = true;
  bool criticalMuCheck = false;  // Output/Critical Mu Check
  // Output/Critical Mu Tolerance and Max Patterns (checkUniqueness).
  double criticalMuTolerance = 1e-6;
  int criticalMuMaxPatterns = 64;
  // Sentences for the log about choices that run but are known to be poor (not errors).
  std::vector<std::string> advice;
  // Sentences for the log about values the scene left to contactlab (automatic coefficients).
  std::vector<std::string> notes;
  // Per contact zone: the formulation's coefficients the scene left at 0 and the values computed
  // for them (FormulationRegistry: automaticCoefficients), reported in summary.json.
  std::map<std::string, std::vector<std::pair<std::string, double>>> automaticCoefficients;
};

// Reads, validates and builds. Collective: every rank calls it with the same arguments.
// Throws InputError (same message on every rank) for anything wrong in the input. `meshes`
// (one rank only; `contactlab batch`): a generated mesh is taken from, or kept in, it.
SceneModel loadScene(SceneFile scene, const Teuchos::RCP<const Comm>& comm,
                     MeshCache* meshes = nullptr);

// Whether some contact zone has friction (mu > 0): the uniqueness checks have something to check.
bool hasFriction(const SceneModel& sm);

// The scene's linear solver (collective).
std::unique_ptr<LinearSolver> buildLinearSolver(const Teuchos::ParameterList& scene,
                                                const Teuchos::RCP<const Comm>& comm);

// The scene's linear solver with its determinant computed, for the uniqueness checks
// (critical-mu, Output/Critical Mu Check): they use the user's solver and settings, so their
// factorizations match the run's. Collective. Throws InputError when the scene's solver cannot
// compute a determinant; call requireDeterminantSolver before solving.
std::unique_ptr<LinearSolver> buildUniquenessCheckSolver(const SceneModel& sm,
                                                         const Teuchos::RCP<const Comm>& comm);

// Throws InputError, before anything runs, when the scene's linear solver cannot compute the
// determinants that `what` needs.
void requireDeterminantSolver(const SceneModel& sm, const std::string& what);

}  // namespace contactlab
