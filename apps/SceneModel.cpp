#include "apps/SceneModel.hpp"

#include "apps/MeshCache.hpp"
#include "apps/SceneContact.hpp"
#include "apps/SceneLoadFunction.hpp"
#include "apps/SceneSchema.hpp"
#include "apps/SceneTemperatures.hpp"
#include "apps/SceneValues.hpp"
#include "base/InputError.hpp"
#include "base/NumberText.hpp"
#include "core/io/OutputFolder.hpp"
#include "core/materials/MaterialRegistry.hpp"
#include "core/mesh/MeshBroadcast.hpp"
#include "core/mesh/MeshSourceRegistry.hpp"
#include "core/problem/CollectiveError.hpp"
#include "core/problem/Problem.hpp"
#include "linear/LinearSolverRegistry.hpp"

#include <Teuchos_DefaultMpiComm.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <tuple>
#include <utility>

namespace contactlab {
namespace {

using Teuchos::ParameterList;

// Runs `build` on rank 0 and broadcasts the mesh; an error there is rethrown on every rank.
std::shared_ptr<Mesh> buildMeshOnRoot(const std::function<std::unique_ptr<Mesh>()>& build,
                                      const Teuchos::RCP<const Comm>& comm) {
  auto mesh = std::make_shared<Mesh>();
  collectively(*comm, [&] {
    if (comm->getRank() == 0) mesh = std::shared_ptr<Mesh>(build());
  });
  broadcastMesh(*mesh, rawMpiComm(comm), 0);
  return mesh;
}

// Loads/<name> of Type centrifugal: density and angular velocity, the axis (2D: z through
// Centre; 3D: Axis through Centre).
CentrifugalLoad centrifugalLoad(const ParameterList& l, const std::string& name, int dim,
                                double endTime, const std::string& where) {
  const std::string path = "Loads/" + name;
  CentrifugalLoad load;
  load.name = name;
  load.block = l.get<std::string>("Block");
  load.density = l.get<double>("Density");
  load.angularVelocity = l.get<double>("Angular Velocity");
  if (!(load.density > 0) || !std::isfinite(load.density))
    throw InputError(where + ": " + path + "/Density must be a finite number > 0");
  if (!std::isfinite(load.angularVelocity))
    throw InputError(where + ": " + path + "/Angular Velocity must be a finite number");
  load.centre = vector3(l, "Centre", where, path, dim);
  if (dim == 3) {
    load.axis = vector3(l, "Axis", where, path, dim);
    const double norm = std::hypot(load.axis[0], load.axis[1], load.axis[2]);
    if (!(norm > 0) || !std::isfinite(norm))
      throw InputError(where + ": " + path + "/Axis must be a non-zero direction");
    for (double& a : load.axis)
      a /= norm;
  } else {
    const auto& axis = l.get<Teuchos::Array<double>>("Axis");
    if (axis.size() != 3 || axis[0] != 0 || axis[1] != 0 || axis[2] == 0)
      throw InputError(where + ": " + path +
                       "/Axis: a 2D model spins about the z axis; leave Axis at [0, 0, 1]");
  }
  const std::string follower = l.get<std::string>("Follower");
  load.follower = follower == "true"    ? SurfaceLoad::Follower::Yes
                  : follower == "false" ? SurfaceLoad::Follower::No
                                        : SurfaceLoad::Follower::Automatic;
  load.function = loadFunction(l, endTime, where, path);
  return load;
}

// Point Groups/<name>: a boundary group of one point cell on the element node nearest to
// Point, added to the mesh (every rank holds the same mesh, so every rank adds the same).
void addPointGroups(const ParameterList& groups, Mesh& mesh, const std::string& where) {
  std::vector<char> elementNode(mesh.numNodes(), 0);
  for (const auto& block : mesh.blocks)
    for (auto n : block.nodes)
      elementNode[n] = 1;
  for (auto it = groups.begin(); it != groups.end(); ++it) {
    const std::string& name = groups.name(it);
    const std::string path = "Point Groups/" + name;
    const ParameterList& g = groups.sublist(name);
    if (!mesh.findBoundaries(name).empty() || !mesh.findBlocks(name).empty())
      throw InputError(where + ": " + path + ": the mesh already has a group named '" + name +
                       "'; choose another name");
    const double tolerance = g.get<double>("Tolerance");
    if (!(tolerance > 0)) throw InputError(where + ": " + path + "/Tolerance must be > 0");
    const auto point = vector3(g, "Point", where, path, mesh.dim);
    const auto [node, distance] = nearestNode(mesh, point, elementNode);
    if (!(distance <= tolerance))
      throw InputError(where + ": " + path + "/Point: the nearest mesh node (" +
                       std::to_string(mesh.nodeId(node)) + ") is " + std::to_string(distance) +
                       " away, farther than Tolerance " + std::to_string(tolerance));
    CellGroup group;
    group.name = name;
    group.type = ElementType::Point1;
    group.nodes = {node};
    group.tags = {0};
    mesh.boundaries.push_back(std::move(group));
  }
}

// Mesh: built on rank 0 (or taken from `contactlab batch`'s cache) and broadcast, with its
// Point Groups added.
std::shared_ptr<Mesh> readMesh(const ParameterList& p, const SceneFile& scene,
                               const Teuchos::RCP<const Comm>& comm, MeshCache* meshes) {
  const ParameterList& meshSection = p.sublist("Mesh");
  const std::string meshType = meshSection.get<std::string>("Type");
  const auto& meshEntry = meshSourceRegistry().get(meshType);
  const std::string& sceneDir = scene.directory;
  const std::string& where = scene.path;
  const auto buildMesh = [&] {
    return buildMeshOnRoot(
        [&] {
          try {
            return meshEntry.build(meshSection.sublist(meshType), sceneDir);
          } catch (const InputError&) {
            throw;
          } catch (const std::exception& e) {
            throw InputError(where + ": Mesh: " + e.what());
          }
        },
        comm);
  };
  // `contactlab batch` keeps generated meshes by their Mesh section; a file is read again (it
  // may have changed between runs).
  const bool cached = meshes && meshType != "file" && comm->getSize() == 1;
  std::ostringstream meshKey;
  if (cached) meshSection.print(meshKey) << sceneDir;
  auto mesh = cached ? meshes->meshFor(meshKey.str(), buildMesh) : buildMesh();
  addPointGroups(p.sublist("Point Groups"), *mesh, where);
  return mesh;
}

// Materials, one per block, and each block's Element Technology.
void readMaterials(const ParameterList& materials, SolidModel& model, const std::string& where) {
  for (auto it = materials.begin(); it != materials.end(); ++it) {
    const std::string& block = materials.name(it);
    const ParameterList& m = materials.sublist(block);
    const std::string type = m.get<std::string>("Type");
    try {
      model.materials[block] = materialRegistry().get(type).build(m.sublist(type));
    } catch (const std::invalid_argument& e) {
      throw InputError(where + ": Materials/" + block + ": " + e.what());
    }
    model.elementTechnologies[block] = m.get<std::string>("Element Technology");
  }
  // Before anything reads the blocks' materials (the contact's automatic coefficients): a
  // material under another name than its block's is named as such.
  try {
    checkBlockMaterials(model);
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
}

void readDirichlet(const ParameterList& dirichlet, SolidModel& model, double endTime,
                   const std::string& where) {
  const int dim = model.mesh->dim;
  for (auto it = dirichlet.begin(); it != dirichlet.end(); ++it) {
    const ParameterList& d = dirichlet.sublist(dirichlet.name(it));
    DirichletCondition bc;
    bc.name = dirichlet.name(it);
    bc.group = d.get<std::string>("Group");
    bc.components = componentList(d, dim, where, "Dirichlet/" + bc.name);
    bc.value = d.get<double>("Value");
    bc.function = loadFunction(d, endTime, where, "Dirichlet/" + bc.name);
    if (bc.group.empty()) throw InputError(where + ": Dirichlet/" + bc.name + "/Group is empty");
    model.dirichlet.push_back(bc);
  }
}

void readSymmetries(const ParameterList& symmetry, SolidModel& model, const std::string& where) {
  const int dim = model.mesh->dim;
  for (auto it = symmetry.begin(); it != symmetry.end(); ++it) {
    const std::string path = "Symmetry/" + symmetry.name(it);
    const ParameterList& s = symmetry.sublist(symmetry.name(it));
    SymmetryCondition condition;
    condition.name = symmetry.name(it);
    condition.group = s.get<std::string>("Group");
    if (condition.group.empty()) throw InputError(where + ": " + path + "/Group is empty");
    condition.normal = vector3(s, "Normal", where, path, dim);
    model.symmetries.push_back(condition);
  }
}

void readTies(const ParameterList& ties, SolidModel& model, double endTime,
              const std::string& where) {
  const int dim = model.mesh->dim;
  for (auto it = ties.begin(); it != ties.end(); ++it) {
    const std::string path = "Ties/" + ties.name(it);
    const ParameterList& t = ties.sublist(ties.name(it));
    TieCondition tie;
    tie.name = ties.name(it);
    for (const std::string& group : t.get<Teuchos::Array<std::string>>("Groups"))
      tie.groups.push_back(group);
    for (double a : t.get<Teuchos::Array<double>>("Coefficients"))
      tie.coefficients.push_back(a);
    if (tie.coefficients.empty() && tie.groups.size() == 2) tie.coefficients = {1.0, -1.0};
    tie.components = componentList(t, dim, where, path);
    tie.value = t.get<double>("Value");
    if (!std::isfinite(tie.value))
      throw InputError(where + ": " + path + "/Value must be a finite number");
    tie.function = loadFunction(t, endTime, where, path);
    model.ties.push_back(tie);
  }
}

void readSprings(const ParameterList& springs, SolidModel& model, const std::string& where) {
  const int dim = model.mesh->dim;
  for (auto it = springs.begin(); it != springs.end(); ++it) {
    const std::string path = "Springs/" + springs.name(it);
    const ParameterList& k = springs.sublist(springs.name(it));
    NodalSpring spring;
    spring.name = springs.name(it);
    spring.group = k.get<std::string>("Group");
    if (spring.group.empty()) throw InputError(where + ": " + path + "/Group is empty");
    spring.components = componentList(k, dim, where, path);
    spring.stiffness = k.get<double>("Stiffness");
    if (!(spring.stiffness > 0) || !std::isfinite(spring.stiffness))
      throw InputError(where + ": " + path + "/Stiffness must be a finite number > 0 (got " +
                       std::to_string(spring.stiffness) + ")");
    model.springs.push_back(spring);
  }
}

void readLoads(const ParameterList& loads, SolidModel& model, double endTime,
               const std::string& where) {
  const int dim = model.mesh->dim;
  for (auto it = loads.begin(); it != loads.end(); ++it) {
    const std::string name = loads.name(it);
    const std::string path = "Loads/" + name;
    const ParameterList& l = loads.sublist(name);
    const std::string type = l.get<std::string>("Type");
    if (type == "body-force") {
      BodyForce b;
      b.name = name;
      b.block = l.get<std::string>("Block");
      b.value = vector3(l, "Vector", where, path, dim);
      b.function = loadFunction(l, endTime, where, path);
      model.bodyForces.push_back(b);
      continue;
    }
    if (type == "centrifugal") {
      model.centrifugalLoads.push_back(centrifugalLoad(l, name, dim, endTime, where));
      // A 2D model's z spin axis is, in axisymmetry, the model's own axis y.
      if (model.axisymmetric) model.centrifugalLoads.back().axis = {0.0, 1.0, 0.0};
      continue;
    }
    if (type != "point-load" && l.get<std::string>("Distribution") != "total")
      throw InputError(where + ": " + path + "/Distribution applies to a point-load only (a " +
                       type + " is spread by its facets or volume); remove the key");
    if (type == "point-load") {
      PointLoad load;
      load.name = name;
      load.group = l.get<std::string>("Group");
      if (load.group.empty()) throw InputError(where + ": " + path + "/Group is empty");
      load.force = vector3(l, "Vector", where, path, dim);
      load.distribution = l.get<std::string>("Distribution") == "per-node"
                              ? PointLoad::Distribution::PerNode
                              : PointLoad::Distribution::Total;
      load.function = loadFunction(l, endTime, where, path);
      model.pointLoads.push_back(load);
      continue;
    }
    const std::string follower = l.get<std::string>("Follower");
    if (type != "pressure" && follower != "automatic")
      throw InputError(
          where + ": " + path +
          "/Follower: only a pressure or a centrifugal load follows the deformation (a " + type +
          " is a dead load); remove the key");
    SurfaceLoad s;
    s.name = name;
    s.follower = follower == "true"    ? SurfaceLoad::Follower::Yes
                 : follower == "false" ? SurfaceLoad::Follower::No
                                       : SurfaceLoad::Follower::Automatic;
    s.group = l.get<std::string>("Group");
    if (s.group.empty()) throw InputError(where + ": " + path + "/Group is empty");
    s.kind = type == "pressure" ? SurfaceLoad::Kind::Pressure : SurfaceLoad::Kind::Traction;
    s.pressure = l.get<double>("Value");
    s.traction = vector3(l, "Vector", where, path, dim);
    s.function = loadFunction(l, endTime, where, path);
    model.surfaceLoads.push_back(s);
  }
}

// Output (the folder, VTK, checkpoints, Contact Times, the uniqueness check) and Initial State.
void readOutput(const ParameterList& output, const ParameterList& initial, const std::string& name,
                SceneModel& sm, const std::string& where) {
  sm.outputDirectory = output.get<std::string>("Directory");
  if (sm.outputDirectory.empty()) sm.outputDirectory = "results/" + name;
  sm.writeVtk = output.get<bool>("VTK");
  sm.initialStateFrom = initial.get<std::string>("From");
  sm.initialStateContinuesTime = initial.get<std::string>("Time") == "continue";
  sm.checkpointEvery = output.get<int>("Checkpoint Every");
  if (sm.checkpointEvery < 0) throw InputError(where + ": Output/Checkpoint Every must be >= 0");
  for (double t : output.get<Teuchos::Array<double>>("Contact Times")) {
    if (!(t > 0) || !(t <= sm.solverOptions.endTime * (1 + 1e-12)))
      throw InputError(where + ": Output/Contact Times: " + numberText(t) +
                       " is not in (0, End Time = " + numberText(sm.solverOptions.endTime) + "]");
    if (!sm.contactTimes.empty() && !(t > sm.contactTimes.back()))
      throw InputError(where + ": Output/Contact Times must increase (" + numberText(t) +
                       " after " + numberText(sm.contactTimes.back()) + ")");
    sm.contactTimes.push_back(t);
  }
  sm.criticalMuCheck = output.get<bool>("Critical Mu Check");
  sm.criticalMuTolerance = output.get<double>("Critical Mu Tolerance");
  sm.criticalMuMaxPatterns = output.get<int>("Critical Mu Max Patterns");
  if (!(sm.criticalMuTolerance >= 0) || !(sm.criticalMuTolerance < 1))
    throw InputError(where + ": Output/Critical Mu Tolerance must be in [0, 1)");
  if (sm.criticalMuMaxPatterns < 1)
    throw InputError(where + ": Output/Critical Mu Max Patterns must be >= 1");
}

// The steps land on every kink of a load function and on the output times, whatever cuts did
// to the step sizes.
void addLandingTimes(SceneModel& sm) {
  std::vector<double>& landing = sm.solverOptions.landingTimes;
  landing = sm.contactTimes;
  const auto addKinks = [&](const auto& prescribed) {
    for (const auto& item : prescribed)
      for (double k : item.function.kinks())
        landing.push_back(k);
  };
  addKinks(sm.model.dirichlet);
  addKinks(sm.model.ties);
  addKinks(sm.model.surfaceLoads);
  addKinks(sm.model.bodyForces);
  addKinks(sm.model.centrifugalLoads);
  addKinks(sm.model.pointLoads);
  addKinks(sm.model.temperatures);
  for (const ContactZone& zone : sm.contact)
    if (zone.obstacle)
      for (double k : zone.obstacle->function.kinks())
        landing.push_back(k);
  std::sort(landing.begin(), landing.end());
  landing.erase(std::unique(landing.begin(), landing.end()), landing.end());
}

void readProbes(const ParameterList& probes, SceneModel& sm, const std::string& where) {
  const int dim = sm.model.mesh->dim;
  for (auto it = probes.begin(); it != probes.end(); ++it) {
    const ParameterList& pr = probes.sublist(probes.name(it));
    Probe probe;
    probe.name = probes.name(it);
    probe.field = pr.get<std::string>("Field");
    probe.point = vector3(pr, "Point", where, "Output/Probes/" + probe.name, dim);
    std::tie(probe.node, probe.distance) = nearestNode(*sm.model.mesh, probe.point, {});
    sm.probes.push_back(probe);
  }
}

void readProfiles(const ParameterList& profiles, SceneModel& sm, const std::string& where) {
  const int dim = sm.model.mesh->dim;
  for (auto it = profiles.begin(); it != profiles.end(); ++it) {
    const ParameterList& pr = profiles.sublist(profiles.name(it));
    const std::string path = "Output/Profiles/" + profiles.name(it);
    Profile profile;
    profile.name = profiles.name(it);
    requirePlainName(profile.name, where + ": Output/Profiles: the name",
                     "its file profile_<name>.csv");
    profile.field = pr.get<std::string>("Field");
    profile.frame = pr.get<std::string>("Frame");
    profile.from = vector3(pr, "From", where, path, dim);
    profile.to = vector3(pr, "To", where, path, dim);
    profile.centre = vector3(pr, "Centre", where, path, dim);
    profile.axis = vector3(pr, "Axis", where, path, 3);
    const int n = pr.get<int>("Points");
    if (n < 2) throw InputError(where + ": " + path + "/Points must be >= 2");
    if (profile.frame == "cylindrical") {
      if (sm.model.axisymmetric)
        throw InputError(where + ": " + path +
                         "/Frame: an axisymmetric model's components "
                         "are cylindrical already (xx = rr, yy = axial, zz = hoop); use "
                         "'cartesian'");
      const auto& a = profile.axis;
      if (dim == 2 && (a[0] != 0 || a[1] != 0))
        throw InputError(where + ": " + path +
                         "/Axis: a 2D model's cylindrical frame turns "
                         "about the z axis; leave Axis at [0, 0, 1]");
      if (!(a[0] * a[0] + a[1] * a[1] + a[2] * a[2] > 0))
        throw InputError(where + ": " + path + "/Axis must not be zero");
    }
    for (int k = 0; k < n; ++k) {
      std::array<double, 3> x{};
      for (int i = 0; i < 3; ++i)
        x[i] = profile.from[i] + (profile.to[i] - profile.from[i]) * k / (n - 1);
      const auto [node, distance] = nearestNode(*sm.model.mesh, x, {});
      profile.points.push_back(x);
      profile.nodes.push_back(node);
      profile.distances.push_back(distance);
    }
    sm.profiles.push_back(profile);
  }
}

}  // namespace

SceneModel loadScene(SceneFile scene, const Teuchos::RCP<const Comm>& comm, MeshCache* meshes) {
  registerAll();
  const std::string& where = scene.path;
  ParameterList& p = *scene.params;
  const bool nameGiven = p.isParameter("Name");
  validateScene(p, where);
  // The name makes the default results folder: a given one must be a plain name (an empty one
  // made results/ itself the folder whose earlier files a run removes), and so must the file's.
  if (nameGiven) scene.name = p.get<std::string>("Name");
  requirePlainName(scene.name,
                   where + (nameGiven ? ": Name" : ": the scene's name (its file name; set Name)"),
                   "the results folder results/<Name>");

  SceneModel sm;
  try {
    sm.solverOptions = StaticSolverOptions::from(p.sublist("Load Steps"), p.sublist("Newton"),
                                                 p.sublist("Algorithm"));
  } catch (const std::invalid_argument& e) {
    throw InputError(where + ": " + e.what());
  }
  SolidModel& model = sm.model;
  model.mesh = readMesh(p, scene, comm, meshes);
  const std::string geometry = p.sublist("Geometry").get<std::string>("Type");
  model.axisymmetric = geometry == "axisymmetric";
  model.planeStress = geometry == "plane-stress";
  readMaterials(p.sublist("Materials"), model, where);
  const double endTime = sm.solverOptions.endTime;
  model.temperatures = blockTemperatures(p.sublist("Temperature"), model, endTime, where);
  readDirichlet(p.sublist("Dirichlet"), model, endTime, where);
  readSymmetries(p.sublist("Symmetry"), model, where);
  readTies(p.sublist("Ties"), model, endTime, where);
  readSprings(p.sublist("Springs"), model, where);
  readLoads(p.sublist("Loads"), model, endTime, where);
  readContactZones(p.sublist("Contact"), sm, where);
  const ParameterList& output = p.sublist("Output");
  readOutput(output, p.sublist("Initial State"), scene.name, sm, where);
  addLandingTimes(sm);
  readProbes(output.sublist("Probes"), sm, where);
  readProfiles(output.sublist("Profiles"), sm, where);
  sm.scene = std::move(scene);
  return sm;
}

bool hasFriction(const SceneModel& sm) {
  for (const auto& zone : sm.contact)
    if (zone.friction > 0) return true;
  return false;
}

std::unique_ptr<LinearSolver> buildLinearSolver(const ParameterList& scene,
                                                const Teuchos::RCP<const Comm>& comm) {
  const ParameterList& section = scene.sublist("Linear Solver");
  const std::string type = section.get<std::string>("Type");
  return linearSolverRegistry().get(type).build(section.sublist(type), comm);
}

void requireDeterminantSolver(const SceneModel& sm, const std::string& what) {
  const std::string type = sm.scene.params->sublist("Linear Solver").get<std::string>("Type");
  if (!computesDeterminant(type))
    throw InputError(
        sm.scene.path + ": " + what + " reads the signs of determinants, and Linear Solver '" +
        type + "' does not compute one (solvers that do: " + solversComputingDeterminant() + ")");
}

std::unique_ptr<LinearSolver> buildUniquenessCheckSolver(const SceneModel& sm,
                                                         const Teuchos::RCP<const Comm>& comm) {
  const ParameterList& section = sm.scene.params->sublist("Linear Solver");
  const std::string type = section.get<std::string>("Type");
  return buildDeterminantSolver(type, section.sublist(type), comm);
}

}  // namespace contactlab
