#include "apps/RunCheckpoint.hpp"

#include "base/InputError.hpp"
#include "core/io/Hdf5Reader.hpp"
#include "core/io/Hdf5Writer.hpp"
#include "core/problem/CollectiveError.hpp"
#include "core/problem/Problem.hpp"
#include "formulations/ContactProblem.hpp"

#include <cstdio>
#include <memory>
#include <sstream>
#include <unordered_map>

namespace contactlab {
namespace {

// Written as the root group's attribute "format": what a reader checks first.
constexpr const char* kFormat = "contactlab checkpoint 1";

std::vector<std::int64_t> nodeIds(const Mesh& mesh) {
  std::vector<std::int64_t> ids(mesh.numNodes());
  for (std::size_t n = 0; n < ids.size(); ++n)
    ids[n] = mesh.nodeId(static_cast<std::int64_t>(n));
  return ids;
}

// Element ids in global element order (block by block): the mesh's element tags.
std::vector<std::int64_t> elementIds(const Mesh& mesh) {
  std::vector<std::int64_t> ids;
  for (const CellGroup& block : mesh.blocks)
    ids.insert(ids.end(), block.tags.begin(), block.tags.end());
  return ids;
}

std::string joinLines(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines)
    out += line + "\n";
  return out;
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

// A count attribute that older checkpoints lack: 0 there.
int countOrZero(const Hdf5Reader& file, const std::string& name) {
  try {
    return static_cast<int>(file.integerAttribute(name));
  } catch (const InputError&) {
    return 0;
  }
}

CheckpointInfo readInfo(const Hdf5Reader& file) {
  std::string format;
  try {
    format = file.stringAttribute("format");
  } catch (const InputError&) {
  }
  if (format != kFormat)
    throw InputError(file.path() + ": not a contactlab checkpoint (attribute format is '" + format +
                     "', expected '" + kFormat + "')");
  CheckpointInfo info;
  info.scenePath = file.stringAttribute("scene_path");
  info.overrides = splitLines(file.stringAttribute("scene_overrides"));
  info.sceneHash = file.stringAttribute("scene_hash");
  info.time = file.doubleAttribute("time");
  info.step = static_cast<int>(file.integerAttribute("step"));
  info.stepSize = file.doubleAttribute("step_size");
  try {
    info.loadReference = file.doubleAttribute("load_reference");
  } catch (const InputError&) {  // written before it: a held first step asks 1e-8 of its start
  }
  info.stepsRows = file.integerAttribute("steps_csv_rows");
  info.vtkFrames = file.integerAttribute("vtk_frames");
  RunTotals& run = info.totals;
  run.iterations = static_cast<int>(file.integerAttribute("newton_iterations"));
  run.linearSolves = static_cast<int>(file.integerAttribute("linear_solves"));
  run.cuts = static_cast<int>(file.integerAttribute("cuts"));
  // Absent from checkpoints written before Newton/Line Search Retry, Newton/Max Update, the
  // halving of unevaluable updates, Newton/Geometry Retry and the round-off stop: such a count
  // starts at 0.
  run.lineSearchRetries = countOrZero(file, "line_search_retries");
  run.geometryRetries = countOrZero(file, "geometry_retries");
  run.limitedUpdates = countOrZero(file, "limited_updates");
  run.unevaluableHalvings = countOrZero(file, "unevaluable_halvings");
  run.roundoffStops = countOrZero(file, "roundoff_stops");
  run.statusIterations = static_cast<int>(file.integerAttribute("status_iterations"));
  run.thresholdIterations = static_cast<int>(file.integerAttribute("threshold_iterations"));
  run.geometryIterations = static_cast<int>(file.integerAttribute("geometry_iterations"));
  const std::vector<std::int64_t> cycling = file.integers("cycling_events");
  for (std::size_t k = 0; k < cycling.size() && k < run.cycling.size(); ++k)
    run.cycling[k] = static_cast<int>(cycling[k]);
  return info;
}

// The first index where two id lists differ, or -1.
std::int64_t firstDifference(const std::vector<std::int64_t>& a,
                             const std::vector<std::int64_t>& b) {
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
    if (a[i] != b[i]) return static_cast<std::int64_t>(i);
  return a.size() == b.size() ? -1 : static_cast<std::int64_t>(std::min(a.size(), b.size()));
}

void checkIds(const std::vector<std::int64_t>& file, const std::vector<std::int64_t>& mesh,
              const std::string& what) {
  if (file.size() != mesh.size())
    throw InputError("the checkpoint's mesh has " + std::to_string(file.size()) + " " + what +
                     "s, this scene's " + std::to_string(mesh.size()) +
                     ": a run starts from a checkpoint of the same mesh");
  const std::int64_t i = firstDifference(file, mesh);
  if (i >= 0)
    throw InputError("the checkpoint's " + what + " " + std::to_string(i + 1) + " has id " +
                     std::to_string(file[i]) + ", this scene's " + std::to_string(mesh[i]) +
                     ": a run starts from a checkpoint of the same mesh");
}

}  // namespace

std::string checkpointPath(const std::string& folder) {
  return folder + "/" + kCheckpointFile;
}

std::string sceneHash(const Teuchos::ParameterList& scene) {
  std::ostringstream text;
  scene.print(text, Teuchos::ParameterList::PrintOptions().showTypes(true));
  // FNV-1a, 64 bits: stable across builds and platforms (std::hash is not).
  std::uint64_t h = 1469598103934665603ull;
  for (const unsigned char c : text.str()) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

void writeCheckpoint(const std::string& path, const CheckpointInfo& info, const Problem& problem,
                     ContactProblem* contact, const Vector& x, const StepContinuation& last) {
  // Collective gathers first; then rank 0 writes, and every rank learns whether it could. The
  // last step's vectors before the history, whose gather leaves x in the surface state.
  const bool hasLast = !last.increment.is_null() && !last.load.is_null();
  std::array<std::vector<double>, 4> lastStep;  // increment, load: displacements, unknowns
  if (hasLast) {
    lastStep[0] = problem.gatherDisplacements(*last.increment);
    lastStep[1] = contact ? contact->pointUnknowns(*last.increment) : std::vector<double>{};
    lastStep[2] = problem.gatherDisplacements(*last.load);
    lastStep[3] = contact ? contact->pointUnknowns(*last.load) : std::vector<double>{};
  }
  std::array<std::vector<double>, 2> previous;  // slow dynamics': displacements, unknowns
  const bool hasPrevious = !last.slowDynamicsPrevious.is_null();
  if (hasPrevious) {
    previous[0] = problem.gatherDisplacements(*last.slowDynamicsPrevious);
    previous[1] =
        contact ? contact->pointUnknowns(*last.slowDynamicsPrevious) : std::vector<double>{};
  }
  const std::vector<double> displacements = problem.gatherDisplacements(x);
  const ElementStates elements = problem.gatherElementStates();
  ContactHistory history;
  if (contact) history = contact->convergedHistory(x);
  const Comm& comm = *problem.dofs().comm();
  collectively(comm, [&] {
    if (comm.getRank() != 0) return;
    const Mesh& mesh = *problem.model().mesh;
    Hdf5Writer file(path);
    file.writeAttribute("format", std::string(kFormat));
    file.writeAttribute("scene_path", info.scenePath);
    file.writeAttribute("scene_overrides", joinLines(info.overrides));
    file.writeAttribute("scene_hash", info.sceneHash);
    file.writeAttribute("ranks", static_cast<std::int64_t>(comm.getSize()));
    file.writeAttribute("dim", static_cast<std::int64_t>(mesh.dim));
    file.writeAttribute("time", info.time);
    file.writeAttribute("step", static_cast<std::int64_t>(info.step));
    file.writeAttribute("step_size", info.stepSize);
    file.writeAttribute("load_reference", info.loadReference);
    file.writeAttribute("steps_csv_rows", info.stepsRows);
    file.writeAttribute("vtk_frames", info.vtkFrames);
    const RunTotals& run = info.totals;
    file.writeAttribute("newton_iterations", static_cast<std::int64_t>(run.iterations));
    file.writeAttribute("linear_solves", static_cast<std::int64_t>(run.linearSolves));
    file.writeAttribute("cuts", static_cast<std::int64_t>(run.cuts));
    file.writeAttribute("line_search_retries", static_cast<std::int64_t>(run.lineSearchRetries));
    file.writeAttribute("geometry_retries", static_cast<std::int64_t>(run.geometryRetries));
    file.writeAttribute("limited_updates", static_cast<std::int64_t>(run.limitedUpdates));
    file.writeAttribute("unevaluable_halvings", static_cast<std::int64_t>(run.unevaluableHalvings));
    file.writeAttribute("roundoff_stops", static_cast<std::int64_t>(run.roundoffStops));
    file.writeAttribute("status_iterations", static_cast<std::int64_t>(run.statusIterations));
    file.writeAttribute("threshold_iterations", static_cast<std::int64_t>(run.thresholdIterations));
    file.writeAttribute("geometry_iterations", static_cast<std::int64_t>(run.geometryIterations));
    file.writeIntegers("cycling_events",
                       std::vector<std::int64_t>(run.cycling.begin(), run.cycling.end()));
    file.writeIntegers("nodes/id", nodeIds(mesh));
    file.writeDoubles("nodes/displacement", displacements, mesh.dim, "length (the mesh's unit)");
    file.writeIntegers("elements/id", elementIds(mesh));
    file.writeIntegers("elements/state_offset", elements.offsets);
    file.writeDoubles("elements/state", elements.values);
    if (contact) {
      std::vector<std::int64_t> ids;
      for (const std::int64_t node : history.node)
        ids.push_back(mesh.nodeId(node));
      file.writeAttribute("contact_ever_closed", static_cast<std::int64_t>(history.everInContact));
      file.writeIntegers("contact/zone", history.zone);
      file.writeIntegers("contact/node_id", ids);
      file.writeIntegers("contact/unknown_offset", history.unknownOffsets);
      file.writeDoubles("contact/unknowns", history.unknowns);
      file.writeDoubles("contact/resistance", history.resistance, 3, "force per area");
      file.writeDoubles("contact/slip", history.slip, 3, "length (the mesh's unit)");
      file.writeIntegers("contact/facet", history.facet);
      file.writeDoubles("contact/frame", history.frame, 3);
    }
    if (hasLast) {
      file.writeDoubles("last_step/increment/displacement", lastStep[0], mesh.dim,
                        "length (the mesh's unit)");
      file.writeDoubles("last_step/increment/unknowns", lastStep[1]);
      file.writeDoubles("last_step/load/displacement", lastStep[2], mesh.dim, "force");
      file.writeDoubles("last_step/load/unknowns", lastStep[3]);
    }
    if (hasPrevious) {
      file.writeDoubles("last_step/slow_dynamics_previous/displacement", previous[0], mesh.dim,
                        "length (the mesh's unit)");
      file.writeDoubles("last_step/slow_dynamics_previous/unknowns", previous[1]);
      file.writeAttribute("last_step_length", last.slowDynamicsStep);
    }
    file.commit();
  });
}

CheckpointInfo readCheckpointInfo(const std::string& path) {
  return readInfo(Hdf5Reader(path));
}

CheckpointInfo restoreCheckpoint(const std::string& path, Problem& problem, ContactProblem* contact,
                                 Vector& x, bool continueTime, StepContinuation* last) {
  const Mesh& mesh = *problem.model().mesh;
  const Comm& comm = *problem.dofs().comm();
  // Reading and checking: every rank reads the same file, and agrees on any failure.
  CheckpointInfo info;
  std::vector<double> displacements;
  ElementStates elements;
  ContactHistory history;
  std::array<std::vector<double>, 4> lastStep;  // as writeCheckpoint's
  std::array<std::vector<double>, 2> previous;
  double previousStep = 0;
  bool hasLast = false, hasPrevious = false;
  collectively(comm, [&] {
    const Hdf5Reader file(path);
    info = readInfo(file);
    hasLast = last != nullptr && file.hasDataset("last_step/increment/displacement");
    if (hasLast) {
      lastStep[0] = file.doubles("last_step/increment/displacement");
      lastStep[1] = file.doubles("last_step/increment/unknowns");
      lastStep[2] = file.doubles("last_step/load/displacement");
      lastStep[3] = file.doubles("last_step/load/unknowns");
    }
    hasPrevious =
        last != nullptr && file.hasDataset("last_step/slow_dynamics_previous/displacement");
    if (hasPrevious) {
      previous[0] = file.doubles("last_step/slow_dynamics_previous/displacement");
      previous[1] = file.doubles("last_step/slow_dynamics_previous/unknowns");
      previousStep = file.doubleAttribute("last_step_length");
    }
    if (file.integerAttribute("dim") != mesh.dim)
      throw InputError("the checkpoint's mesh is " + std::to_string(file.integerAttribute("dim")) +
                       "D, this scene's " + std::to_string(mesh.dim) + "D");
    checkIds(file.integers("nodes/id"), nodeIds(mesh), "node");
    checkIds(file.integers("elements/id"), elementIds(mesh), "element");
    displacements = file.doubles("nodes/displacement");
    elements.offsets = file.integers("elements/state_offset");
    elements.values = file.doubles("elements/state");
    const bool hasContact = file.hasDataset("contact/zone");
    if (hasContact != (contact != nullptr))
      throw InputError(hasContact ? "the checkpoint has contact points, this scene no contact"
                                  : "the checkpoint has no contact points, this scene has "
                                    "contact zones");
    if (!contact) return;
    history.zone = file.integers("contact/zone");
    std::unordered_map<std::int64_t, std::int64_t> indexOfId;
    for (std::size_t n = 0; n < mesh.numNodes(); ++n)
      indexOfId[mesh.nodeId(static_cast<std::int64_t>(n))] = static_cast<std::int64_t>(n);
    for (const std::int64_t id : file.integers("contact/node_id"))
      history.node.push_back(indexOfId.at(id));
    history.unknownOffsets = file.integers("contact/unknown_offset");
    history.unknowns = file.doubles("contact/unknowns");
    history.resistance = file.doubles("contact/resistance");
    history.slip = file.doubles("contact/slip");
    history.facet = file.integers("contact/facet");
    if (file.hasDataset("contact/frame")) history.frame = file.doubles("contact/frame");
    history.everInContact = file.integerAttribute("contact_ever_closed") != 0;
  });
  // The same data on every rank: a mismatch throws on every rank alike.
  problem.scatterDisplacements(displacements, x);
  problem.setElementStates(elements);
  if (contact) contact->restoreHistory(history, x, continueTime ? info.time : 0.0);
  if (last) *last = {};
  if (hasLast) {
    for (int v = 0; v < 2; ++v) {
      Teuchos::RCP<Vector> vector = Teuchos::rcp(new Vector(x.getMap()));
      problem.scatterDisplacements(lastStep[2 * v], *vector);
      if (contact) contact->setPointUnknowns(lastStep[2 * v + 1], *vector);
      (v == 0 ? last->increment : last->load) = vector;
    }
  }
  if (hasPrevious) {
    Teuchos::RCP<Vector> vector = Teuchos::rcp(new Vector(x.getMap()));
    problem.scatterDisplacements(previous[0], *vector);
    if (contact) contact->setPointUnknowns(previous[1], *vector);
    last->slowDynamicsPrevious = vector;
    last->slowDynamicsStep = previousStep;
  }
  return info;
}

}  // namespace contactlab
