#include "apps/SceneModel.hpp"

#include "apps/AutomaticAugmentation.hpp"
#include "apps/MeshCache.hpp"
#include "apps/SceneLoadFunction.hpp"
#include "apps/SceneSchema.hpp"
#include "apps/SceneTemperatures.hpp"
#include "base/InputError.hpp"
#include "base/NumberText.hpp"
#include "core/contact/MortarIntegration.hpp"
#include "core/io/OutputFolder.hpp"
#include "core/materials/MaterialRegistry.hpp"
#include "core/mesh/MeshBroadcast.hpp"
#include "core/mesh/MeshSourceRegistry.hpp"
#include "core/problem/CollectiveError.hpp"
#include "core/problem/Problem.hpp"
#include "formulations/FormulationRegistry.hpp"
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

std::array<double, 3> vector3(const ParameterList& p, const std::string& key,
                              const std::string& where, const std::string& path, int dim) {
  const auto& v = p.get<Teuchos::Array<double>>(key);
  if (static_cast<int>(v.size()) != dim && static_cast<int>(v.size()) != 3)
    throw InputError(where + ": " + path + "/" + key + " must have " + std::to_string(dim) +
                     " components");
  // A 2D model has no z: a z component that is not zero would be dropped without a word.
  if (dim == 2 && v.size() == 3 && v[2] != 0.0)
    throw InputError(where + ": " + path + "/" + key + " has a z component (" +
                     std::to_string(v[2]) + ") in a 2D model: give 2 components, or z = 0");
  std::array<double, 3> out{};
  for (int i = 0; i < dim; ++i)
    out[i] = v[i];
  return out;
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

// Components: 'xyz' is "every component"; a z named on its own in 2D would act on nothing.
std::vector<int> componentList(const ParameterList& p, int dim, const std::string& where,
                               const std::string& path) {
  const std::string components = p.get<std::string>("Components");
  if (dim == 2 && components != "xyz" && components.find('z') != std::string::npos)
    throw InputError(where + ": " + path + "/Components: '" + components +
                     "' names z in a 2D model, which has x and y only");
  std::vector<int> list;
  for (char c : components)
    if (c - 'x' < dim) list.push_back(c - 'x');
  return list;
}

// The mesh node closest to `point` among those with usable[n] != 0 (every node when `usable`
// is empty), and its distance.
std::pair<std::int64_t, double> nearestNode(const Mesh& mesh, const std::array<double, 3>& point,
                                            const std::vector<char>& usable) {
  double best = std::numeric_limits<double>::max();
  std::int64_t node = -1;
  for (std::size_t n = 0; n < mesh.numNodes(); ++n) {
    if (!usable.empty() && !usable[n]) continue;
    double d2 = 0;
    for (int i = 0; i < 3; ++i)
      d2 += std::pow(mesh.coords[3 * n + i] - point[i], 2);
    if (d2 < best) best = d2, node = static_cast<std::int64_t>(n);
  }
  return {node, std::sqrt(best)};
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

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names)
    s += (s.empty() ? "" : ", ") + n;
  return s;
}

// The first facet group of `slave` whose corners carry no share of a smooth pressure (tri6,
// quad8: hasTransformedBasis), or null.
const CellGroup* cornerlessFacets(const Mesh& mesh, const std::string& slave) {
  for (const CellGroup* g : mesh.findBoundaries(slave))
    if (hasTransformedBasis(g->type)) return g;
  return nullptr;
}

// Contact/<zone>: checked against the mesh (the same on every rank, so every rank agrees).
ContactZone contactZone(const ParameterList& z, const std::string& name, const Mesh& mesh,
                        const SolidModel& model, double endTime, const std::string& where,
                        std::vector<std::string>& notes,
                        std::map<std::string, double>& automaticNormalAugmentation,
                        std::map<std::string, double>& automaticTangentialAugmentation) {
  const std::string path = where + ": Contact/" + name;
  ContactZone zone;
  zone.name = name;
  zone.slave = z.get<std::string>("Slave");
  zone.master = z.get<std::string>("Master");
  auto isBoundary = [&](const std::string& group) { return !mesh.findBoundaries(group).empty(); };
  const std::string boundaries = joined(mesh.boundaryNames());
  if (zone.slave.empty())
    throw InputError(
        path + "/Slave is empty; give a boundary physical group (one of: " + boundaries + ")");
  if (!isBoundary(zone.slave))
    throw InputError(path + "/Slave: '" + zone.slave + "' is not a boundary group of the mesh " +
                     "(boundary groups: " + boundaries + ")");
  const bool obstacle = z.isSublist("Obstacle");
  if (obstacle && !zone.master.empty())
    throw InputError(path +
                     ": give either Master (a second body) or Obstacle (a rigid "
                     "surface), not both");
  if (!obstacle && zone.master.empty())
    throw InputError(path + ": give a Master boundary group or an Obstacle");
  if (!obstacle && !isBoundary(zone.master))
    throw InputError(path + "/Master: '" + zone.master + "' is not a boundary group of the " +
                     "mesh (boundary groups: " + boundaries + ")");
  if (zone.slave == zone.master)
    throw InputError(path + ": Slave and Master are the same group '" + zone.slave +
                     "' (self-contact within one group is not supported; two groups of one "
                     "body that share no node are, e.g. the two sides of a fold)");
  if (!obstacle) {
    // A node on both sides would be paired with its own surface (a gap of 0 from the start).
    const std::vector<std::int64_t> s = mesh.boundaryNodes(zone.slave);
    const std::vector<std::int64_t> m = mesh.boundaryNodes(zone.master);
    std::vector<std::int64_t> shared;
    std::set_intersection(s.begin(), s.end(), m.begin(), m.end(), std::back_inserter(shared));
    if (!shared.empty())
      throw InputError(path + ": Slave '" + zone.slave + "' and Master '" + zone.master +
                       "' share " + std::to_string(shared.size()) + " node(s) (e.g. node " +
                       std::to_string(mesh.nodeId(shared.front())) +
                       "): a node cannot be paired with its own surface; make the groups "
                       "disjoint");
  }
  zone.noFrictionGroup = z.get<std::string>("No Friction Group");
  if (!zone.noFrictionGroup.empty() && !isBoundary(zone.noFrictionGroup))
    throw InputError(path + "/No Friction Group: '" + zone.noFrictionGroup +
                     "' is not a boundary group of the mesh (boundary groups: " + boundaries + ")");
  zone.noContactGroup = z.get<std::string>("No Contact Group");
  if (!zone.noContactGroup.empty()) {
    if (!isBoundary(zone.noContactGroup))
      throw InputError(path + "/No Contact Group: '" + zone.noContactGroup +
                       "' is not a boundary group of the mesh (boundary groups: " + boundaries +
                       ")");
    const auto excluded = mesh.boundaryNodes(zone.noContactGroup);
    const auto slaves = mesh.boundaryNodes(zone.slave);
    if (std::none_of(excluded.begin(), excluded.end(), [&](std::int64_t n) {
          return std::binary_search(slaves.begin(), slaves.end(), n);
        }))
      throw InputError(path + "/No Contact Group: '" + zone.noContactGroup +
                       "' holds no node of Slave '" + zone.slave + "'");
  }
  zone.friction = z.get<double>("Friction");
  if (!(zone.friction >= 0) || !std::isfinite(zone.friction))
    throw InputError(path + "/Friction must be a finite number >= 0 (got " +
                     std::to_string(zone.friction) + ")");
  zone.searchDistance = z.get<double>("Search Distance");
  if (!(zone.searchDistance >= 0))
    throw InputError(path + "/Search Distance must be >= 0 (0 = automatic)");
  const std::string initial = z.get<std::string>("Initial Contact");
  zone.initialContact = initial == "all"    ? InitialContact::all
                        : initial == "none" ? InitialContact::none
                                            : InitialContact::interpenetrated;
  const std::string discretization = z.get<std::string>("Discretization");
  zone.discretization =
      discretization == "mortar" ? Discretization::mortar : Discretization::nodeToSegment;
  zone.multiplierBasis = z.get<std::string>("Multiplier Basis") == "standard"
                             ? MultiplierBasis::Standard
                             : MultiplierBasis::Dual;
  if (obstacle) {
    const ParameterList& o = z.sublist("Obstacle");
    RigidObstacleSpec spec;
    const std::string type = o.get<std::string>("Type");
    spec.shape = type == "plane"    ? RigidObstacleSpec::Shape::Plane
                 : type == "sphere" ? RigidObstacleSpec::Shape::Sphere
                                    : RigidObstacleSpec::Shape::Cylinder;
    spec.side = o.get<std::string>("Side") == "inside" ? RigidObstacleSpec::Side::Inside
                                                       : RigidObstacleSpec::Side::Outside;
    const std::string opath = "Contact/" + name + "/Obstacle";
    spec.point = vector3(o, "Point", where, opath, mesh.dim);
    spec.direction = vector3(o, type == "cylinder" ? "Axis" : "Normal", where, opath,
                             type == "cylinder" ? 3 : mesh.dim);
    spec.radius = o.get<double>("Radius");
    spec.displacement = vector3(o, "Displacement", where, opath, mesh.dim);
    spec.function = loadFunction(o, endTime, where, opath);
    try {
      RigidObstacle check(spec, mesh.dim);
    } catch (const std::invalid_argument& e) {
      throw InputError(path + "/Obstacle: " + e.what());
    }
    zone.obstacle = spec;
  }
  const ParameterList& f = z.sublist("Formulation");
  zone.formulation = f.get<std::string>("Type");
  ParameterList params = f.sublist(zone.formulation);
  // The contact stiffness E / h, the scale of the contact equations' residual as forces
  // (LawOutput::normalRowForce); unknown (0) where no block bounded by the surfaces has a
  // material, which the automatic r_n below then reports.
  std::optional<AugmentationScale> stiffness;
  std::string noStiffness;  // why, when there is none
  try {
    stiffness = automaticAugmentation(mesh, model.materials, zone.slave, zone.master);
    zone.stiffnessScale = stiffness->normalAugmentation();
  } catch (const std::invalid_argument& e) {
    noStiffness = e.what();
  }
  // The augmented Lagrangian's Normal Augmentation or Lagrange's Normal Complementarity Constant
  // at 0 (their default): E / h from the model (AutomaticAugmentation.hpp).
  const bool lagrangeConstant = params.isParameter("Normal Complementarity Constant");
  const std::string normalKey =
      lagrangeConstant ? "Normal Complementarity Constant" : "Normal Augmentation";
  if (params.isParameter(normalKey) && params.get<double>(normalKey) == 0.0) {
    if (!stiffness)
      throw InputError(path + "/Formulation/" + zone.formulation + "/" + normalKey +
                       ": automatic (0) cannot be computed: " + noStiffness +
                       "; give a value (start near E/h)");
    params.set(normalKey, stiffness->normalAugmentation());
    automaticNormalAugmentation[name] = stiffness->normalAugmentation();
    notes.push_back("Contact/" + name + ": " + normalKey + (lagrangeConstant ? " c_n" : " r_n") +
                    " = E / h = " + numberText(stiffness->normalAugmentation()) +
                    " (automatic: E = " + numberText(stiffness->youngModulus) +
                    ", the softer body's; h = " + numberText(stiffness->facetSize) +
                    ", the slave facets' median edge)");
  }
  // Tangential Augmentation 0 (its default) with friction: from the model too.
  if (zone.friction > 0 && stiffness && params.isParameter("Tangential Augmentation") &&
      params.get<double>("Tangential Augmentation") == 0.0) {
    const double rt = stiffness->tangentialAugmentation(zone.friction);
    params.set("Tangential Augmentation", rt);
    automaticTangentialAugmentation[name] = rt;
    notes.push_back("Contact/" + name + ": Tangential Augmentation r_t = 1 / (" +
                    numberText(kAutomaticContactStrain) + " mu h) = " + numberText(rt) +
                    " (automatic: mu = " + numberText(zone.friction) +
                    ", h = " + numberText(stiffness->facetSize) + ")");
  }
  // Coefficients the user gave far from the model's scale: said if the run fails.
  if (stiffness) {
    const std::string where = path + "/Formulation/" + zone.formulation + "/";
    std::vector<std::string> advice;
    if (params.isParameter(normalKey) && !automaticNormalAugmentation.count(name))
      advice.push_back(augmentationAdvice(where + normalKey, params.get<double>(normalKey),
                                          stiffness->normalAugmentation()));
    if (zone.friction > 0 && params.isParameter("Tangential Augmentation") &&
        !automaticTangentialAugmentation.count(name))
      advice.push_back(augmentationAdvice(where + "Tangential Augmentation",
                                          params.get<double>("Tangential Augmentation"),
                                          stiffness->tangentialAugmentation(zone.friction)));
    for (const std::string& a : advice)
      if (!a.empty()) zone.coefficientAdvice += (zone.coefficientAdvice.empty() ? "" : "; ") + a;
  }
  try {
    zone.law = formulationRegistry().get(zone.formulation).build(params);
  } catch (const std::invalid_argument& e) {
    throw InputError(path + "/Formulation/" + zone.formulation + ": " + e.what());
  }
  // 'automatic': mortar on tri6 and quad8 slave facets, whose corners carry no share (or a
  // negative one) of a smooth pressure, so that node-to-segment's collocation there is not
  // sound (a uniform pressure on hex20 against a plane comes out with a 13 % spread, 3D Hertz
  // in tet10 with friction failed to converge); node-to-segment elsewhere, and for a normal
  // field, which mortar does not pair (doc/verification.md "Mortar against an obstacle").
  if (discretization == "automatic" && !zone.law->hasNormalField())
    if (const CellGroup* g = cornerlessFacets(mesh, zone.slave)) {
      zone.discretization = Discretization::mortar;
      notes.push_back("Contact/" + name + ": Discretization mortar (automatic: " +
                      info(g->type).name + " slave facets)");
    }
  if (zone.law->hasNormalField() && zone.discretization == Discretization::mortar)
    throw InputError(path + "/Formulation: " + zone.formulation +
                     " runs with node-to-segment (against a master surface or an obstacle), not "
                     "mortar (its normal is the master's at a point, which mortar does not "
                     "pair)");
  if (zone.initialContact != InitialContact::interpenetrated && !zone.law->hasMultipliers())
    throw InputError(path + "/Initial Contact: '" + initial + "' sets the starting statuses " +
                     "through the contact multipliers, and " + zone.formulation +
                     " has none; use 'interpenetrated' or a formulation with multipliers " +
                     "(lagrange, augmented-lagrangian)");
  // With friction the tangential coefficient is used: it must be given.
  for (const char* key : {"Tangential Penalty", "Tangential Augmentation"})
    if (zone.friction > 0 && params.isParameter(key) && !(params.get<double>(key) > 0))
      throw InputError(path + "/Formulation/" + zone.formulation + "/" + key +
                       " must be > 0 when Friction > 0");
  return zone;
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

  // Mesh.
  const ParameterList& meshSection = p.sublist("Mesh");
  const std::string meshType = meshSection.get<std::string>("Type");
  const auto& meshEntry = meshSourceRegistry().get(meshType);
  const std::string sceneDir = scene.directory;
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
  sm.model.mesh = mesh;
  const std::string geometry = p.sublist("Geometry").get<std::string>("Type");
  sm.model.axisymmetric = geometry == "axisymmetric";
  sm.model.planeStress = geometry == "plane-stress";
  const int dim = mesh->dim;

  // Materials, one per block.
  const ParameterList& materials = p.sublist("Materials");
  for (auto it = materials.begin(); it != materials.end(); ++it) {
    const std::string& block = materials.name(it);
    const ParameterList& m = materials.sublist(block);
    const std::string type = m.get<std::string>("Type");
    try {
      sm.model.materials[block] = materialRegistry().get(type).build(m.sublist(type));
    } catch (const std::invalid_argument& e) {
      throw InputError(where + ": Materials/" + block + ": " + e.what());
    }
    sm.model.elementTechnologies[block] = m.get<std::string>("Element Technology");
  }
  // Before anything reads the blocks' materials (the contact's automatic coefficients): a
  // material under another name than its block's is named as such.
  try {
    checkBlockMaterials(sm.model);
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }

  const double endTime = sm.solverOptions.endTime;
  sm.model.temperatures = blockTemperatures(p.sublist("Temperature"), sm.model, endTime, where);
  const ParameterList& dirichlet = p.sublist("Dirichlet");
  for (auto it = dirichlet.begin(); it != dirichlet.end(); ++it) {
    const ParameterList& d = dirichlet.sublist(dirichlet.name(it));
    DirichletCondition bc;
    bc.name = dirichlet.name(it);
    bc.group = d.get<std::string>("Group");
    bc.components = componentList(d, dim, where, "Dirichlet/" + bc.name);
    bc.value = d.get<double>("Value");
    bc.function = loadFunction(d, endTime, where, "Dirichlet/" + bc.name);
    if (bc.group.empty()) throw InputError(where + ": Dirichlet/" + bc.name + "/Group is empty");
    sm.model.dirichlet.push_back(bc);
  }

  const ParameterList& symmetry = p.sublist("Symmetry");
  for (auto it = symmetry.begin(); it != symmetry.end(); ++it) {
    const std::string path = "Symmetry/" + symmetry.name(it);
    const ParameterList& s = symmetry.sublist(symmetry.name(it));
    SymmetryCondition condition;
    condition.name = symmetry.name(it);
    condition.group = s.get<std::string>("Group");
    if (condition.group.empty()) throw InputError(where + ": " + path + "/Group is empty");
    condition.normal = vector3(s, "Normal", where, path, dim);
    sm.model.symmetries.push_back(condition);
  }

  const ParameterList& ties = p.sublist("Ties");
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
    sm.model.ties.push_back(tie);
  }

  const ParameterList& springs = p.sublist("Springs");
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
    sm.model.springs.push_back(spring);
  }

  const ParameterList& loads = p.sublist("Loads");
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
      sm.model.bodyForces.push_back(b);
      continue;
    }
    if (type == "centrifugal") {
      sm.model.centrifugalLoads.push_back(centrifugalLoad(l, name, dim, endTime, where));
      // A 2D model's z spin axis is, in axisymmetry, the model's own axis y.
      if (sm.model.axisymmetric) sm.model.centrifugalLoads.back().axis = {0.0, 1.0, 0.0};
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
      sm.model.pointLoads.push_back(load);
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
    sm.model.surfaceLoads.push_back(s);
  }

  // Contact zones.
  const ParameterList& contact = p.sublist("Contact");
  for (auto it = contact.begin(); it != contact.end(); ++it)
    sm.contact.push_back(contactZone(
        contact.sublist(contact.name(it)), contact.name(it), *mesh, sm.model, endTime, where,
        sm.notes, sm.automaticNormalAugmentation, sm.automaticTangentialAugmentation));
  // Node-to-segment collocates at the slave nodes, and tri6/quad8 corners carry no (or a
  // negative) share of a smooth pressure: it runs, its forces are not consistent loads.
  for (const ContactZone& zone : sm.contact)
    if (zone.discretization == Discretization::nodeToSegment)
      if (const CellGroup* g = cornerlessFacets(*mesh, zone.slave))
        sm.advice.push_back(
            "Contact/" + zone.name + ": node-to-segment on " + info(g->type).name +
            " slave facets collocates at corners that carry no share of a smooth pressure "
            "(a uniform pressure on tet10 comes out with a 7 % spread, 3D Hertz on two tet10 "
            "bodies 5.5 % RMS off); 'Discretization: mortar' enforces contact on quadratic "
            "facets soundly, against a master surface or an obstacle (1e-12 and 3.2 %, "
            "doc/verification.md)");
  // Combinations that cannot work are refused here, with the reason.
  for (const ContactZone& zone : sm.contact)
    if (sm.solverOptions.cyclingTreatment == "automatic" && zone.law->coefficientsChangeSolution())
      throw InputError(where +
                       ": Algorithm/Cycling Treatment 'automatic' adapts the formulation's "
                       "coefficients, but in Contact/" +
                       zone.name + " the formulation '" + zone.formulation +
                       "' takes them as part of the model (they set the "
                       "penetration and the solution); use 'forced' or 'none', or a formulation "
                       "with multipliers");

  // Output and probes.
  const ParameterList& output = p.sublist("Output");
  sm.outputDirectory = output.get<std::string>("Directory");
  if (sm.outputDirectory.empty()) sm.outputDirectory = "results/" + scene.name;
  sm.writeVtk = output.get<bool>("VTK");
  const ParameterList& initial = p.sublist("Initial State");
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
  // The steps land on every kink of a load function and on the output times, whatever cuts
  // did to the step sizes.
  std::vector<double>& landing = sm.solverOptions.landingTimes;
  landing = sm.contactTimes;
  const auto addKinks = [&](const auto& prescribed) {
    for (const auto& item : prescribed)
      for (double k : item.function.kinks())
        landing.push_back(k);
  };
  addKinks(sm.model.dirichlet);
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
  sm.criticalMuCheck = output.get<bool>("Critical Mu Check");
  sm.criticalMuTolerance = output.get<double>("Critical Mu Tolerance");
  sm.criticalMuMaxPatterns = output.get<int>("Critical Mu Max Patterns");
  if (!(sm.criticalMuTolerance >= 0) || !(sm.criticalMuTolerance < 1))
    throw InputError(where + ": Output/Critical Mu Tolerance must be in [0, 1)");
  if (sm.criticalMuMaxPatterns < 1)
    throw InputError(where + ": Output/Critical Mu Max Patterns must be >= 1");
  const ParameterList& probes = output.sublist("Probes");
  for (auto it = probes.begin(); it != probes.end(); ++it) {
    const ParameterList& pr = probes.sublist(probes.name(it));
    Probe probe;
    probe.name = probes.name(it);
    probe.field = pr.get<std::string>("Field");
    probe.point = vector3(pr, "Point", where, "Output/Probes/" + probe.name, dim);
    std::tie(probe.node, probe.distance) = nearestNode(*mesh, probe.point, {});
    sm.probes.push_back(probe);
  }
  const ParameterList& profiles = output.sublist("Profiles");
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
      const auto [node, distance] = nearestNode(*mesh, x, {});
      profile.points.push_back(x);
      profile.nodes.push_back(node);
      profile.distances.push_back(distance);
    }
    sm.profiles.push_back(profile);
  }
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
