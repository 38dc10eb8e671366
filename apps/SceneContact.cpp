#include "apps/SceneContact.hpp"

#include "apps/SceneLoadFunction.hpp"
#include "apps/SceneValues.hpp"
#include "base/InputError.hpp"
#include "formulations/ContactDiscretizationType.hpp"
#include "formulations/FormulationRegistry.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>

namespace contactlab {
namespace {

using Teuchos::ParameterList;

// Slave and Master (or an Obstacle), No Friction Group and No Contact Group, checked against
// the mesh's boundary groups (the same on every rank, so every rank agrees).
void readSurfaces(const ParameterList& z, const std::string& path, const Mesh& mesh,
                  ContactZone& zone) {
  zone.slave = z.get<std::string>("Slave");
  zone.master = z.get<std::string>("Master");
  auto isBoundary = [&](const std::string& group) { return !mesh.findBoundaries(group).empty(); };
  const std::string boundaries = joinedNames(mesh.boundaryNames());
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
}

// Contact/<zone>/Obstacle: a rigid plane, sphere or cylinder and its motion.
RigidObstacleSpec obstacleSpec(const ParameterList& o, const std::string& name, const Mesh& mesh,
                               double endTime, const std::string& where, const std::string& path) {
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
  return spec;
}

// The formulation's coefficients left at 0 (automatic) from the zone's contact scale E / h
// (FormulationRegistry: automaticCoefficients), said in the notes; and, for a failed run's
// message, the given ones more than a decade from what 0 would have given.
void fillAutomaticCoefficients(ParameterList& params, ContactZone& zone, const std::string& path,
                               SceneModel& sm) {
  // Also the scale of the contact equations' residual as forces (LawOutput::normalRowForce);
  // unknown (0) where no block bounded by the surfaces has a material.
  std::optional<ContactScale> scale;
  std::string noScale;  // why, when there is none
  try {
    scale = contactScale(*sm.model.mesh, sm.model.materials, zone.slave, zone.master);
    zone.stiffnessScale = scale->stiffness();
  } catch (const std::invalid_argument& e) {
    noScale = e.what();
  }
  const std::string where = path + "/Formulation/" + zone.formulation + "/";
  for (const AutomaticCoefficient& c : automaticCoefficients(zone.formulation)) {
    if (c.needsFriction && !(zone.friction > 0)) continue;
    const double given = params.get<double>(c.key);
    if (given == 0.0) {
      if (!scale && c.needsFriction) continue;  // the missing material is reported below
      if (!scale)
        throw InputError(where + c.key + ": automatic (0) cannot be computed: " + noScale +
                         "; give a value (start near E/h)");
      const double value = c.value(*scale, zone.friction);
      params.set(c.key, value);
      sm.automaticCoefficients[zone.name].emplace_back(c.key, value);
      sm.notes.push_back("Contact/" + zone.name + ": " + c.note(*scale, zone.friction, value));
    } else if (scale) {
      const std::string advice =
          coefficientAdvice(where + c.key, given, c.value(*scale, zone.friction));
      if (!advice.empty())
        zone.coefficientAdvice += (zone.coefficientAdvice.empty() ? "" : "; ") + advice;
    }
  }
}

// Discretization: a registry name, or automatic's pick (noted with its reason); refused when
// the zone's formulation cannot run on it.
void readDiscretization(const ParameterList& z, const std::string& path, const Mesh& mesh,
                        ContactZone& zone, std::vector<std::string>& notes) {
  const std::string requested = z.get<std::string>("Discretization");
  zone.discretization = requested;
  if (requested == "automatic") {
    const AutomaticDiscretization pick = chooseAutomaticDiscretization(mesh, zone.slave, *zone.law);
    zone.discretization = pick.name;
    if (!pick.reason.empty())
      notes.push_back("Contact/" + zone.name + ": Discretization " + pick.name +
                      " (automatic: " + pick.reason + ")");
  }
  const std::string refusal = contactDiscretizationType(zone.discretization).refusal(*zone.law);
  if (!refusal.empty()) throw InputError(path + "/Discretization: " + refusal);
}

// Contact/<zone>.
ContactZone contactZone(const ParameterList& z, const std::string& name, SceneModel& sm,
                        const std::string& where) {
  const Mesh& mesh = *sm.model.mesh;
  const std::string path = where + ": Contact/" + name;
  ContactZone zone;
  zone.name = name;
  readSurfaces(z, path, mesh, zone);
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
  zone.multiplierBasis = z.get<std::string>("Multiplier Basis") == "standard"
                             ? MultiplierBasis::Standard
                             : MultiplierBasis::Dual;
  if (z.isSublist("Obstacle"))
    zone.obstacle =
        obstacleSpec(z.sublist("Obstacle"), name, mesh, sm.solverOptions.endTime, where, path);
  const ParameterList& f = z.sublist("Formulation");
  zone.formulation = f.get<std::string>("Type");
  ParameterList params = f.sublist(zone.formulation);
  fillAutomaticCoefficients(params, zone, path, sm);
  try {
    zone.law = formulationRegistry().get(zone.formulation).build(params);
  } catch (const std::invalid_argument& e) {
    throw InputError(path + "/Formulation/" + zone.formulation + ": " + e.what());
  }
  readDiscretization(z, path, mesh, zone, sm.notes);
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

void readContactZones(const ParameterList& contact, SceneModel& sm, const std::string& where) {
  for (auto it = contact.begin(); it != contact.end(); ++it)
    sm.contact.push_back(
        contactZone(contact.sublist(contact.name(it)), contact.name(it), sm, where));
  // Node-to-segment collocates at the slave nodes, and tri6/quad8 corners carry no (or a
  // negative) share of a smooth pressure: it runs, its forces are not consistent loads.
  for (const ContactZone& zone : sm.contact)
    if (contactDiscretizationType(zone.discretization).traits().collocatesAtSlaveNodes)
      if (const CellGroup* g = cornerlessFacets(*sm.model.mesh, zone.slave))
        sm.advice.push_back(
            "Contact/" + zone.name + ": " + zone.discretization + " on " + info(g->type).name +
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
}

}  // namespace contactlab
