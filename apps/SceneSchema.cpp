#include "apps/SceneSchema.hpp"

#include "algorithms/StaticSolver.hpp"
#include "base/InputError.hpp"
#include "base/NumberText.hpp"
#include "core/io/ParameterValidation.hpp"
#include "core/materials/MaterialRegistry.hpp"
#include "core/mesh/MeshSourceRegistry.hpp"
#include "core/problem/ElementTechnology.hpp"
#include "formulations/ContactDiscretizationType.hpp"
#include "formulations/FormulationRegistry.hpp"
#include "linear/LinearSolverRegistry.hpp"

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include <sstream>

namespace contactlab {
namespace {

using Teuchos::ParameterList;

Teuchos::RCP<const Teuchos::ParameterEntryValidator> choices(const std::vector<std::string>& v) {
  return Teuchos::rcp(new Teuchos::StringValidator(Teuchos::Array<std::string>(v)));
}

// `Type: <name>` plus the sublist of that type's parameters.
template <class RegistryT>
ParameterList typedSection(const RegistryT& registry, const ParameterList* user,
                           const std::string& defaultType, const std::string& where,
                           const std::string& path) {
  std::string type = defaultType;
  if (user && user->isParameter("Type")) {
    if (!user->isType<std::string>("Type"))
      throw InputError(where + ": " + path + "/Type must be a string");
    type = user->get<std::string>("Type");
  }
  if (!registry.has(type))
    throw InputError(where + ": unknown " + registry.axis() + " '" + type + "' in " + path +
                     "/Type; valid choices: " + registry.joinedNames());
  ParameterList section(path);
  section.set("Type", defaultType,
              "The " + registry.axis() + " (one of: " + registry.joinedNames() + ")",
              choices(registry.names()));
  section.set(type, *registry.get(type).validParameters());
  // Parameters of other types may stay next to the chosen one (validated, unused), so that a
  // scene can switch type with a single --set Type=... (studies do).
  if (user)
    for (const auto& other : registry.names())
      if (other != type && user->isSublist(other))
        section.set(other, *registry.get(other).validParameters());
  return section;
}

const ParameterList* userSublist(const ParameterList* user, const std::string& key) {
  return user && user->isSublist(key) ? &user->sublist(key) : nullptr;
}

// A section holding one sublist per user-chosen name, each following `item`.
ParameterList namedSection(
    const ParameterList* user, const std::string& path, const std::string& where,
    const std::function<ParameterList(const ParameterList&, const std::string&)>& item) {
  ParameterList section(path);
  if (!user) return section;
  for (auto it = user->begin(); it != user->end(); ++it) {
    const std::string& name = user->name(it);
    if (!user->entry(it).isList())
      throw InputError(where + ": " + path + "/" + name + " must be a sublist (e.g. " + name +
                       ": {Group: top, ...})");
    section.set(name, item(user->sublist(name), path + "/" + name));
  }
  return section;
}

// The time function of a prescribed value (Dirichlet, load, obstacle): Function, documented by
// `functionDoc`, then Start Time and Stop Time of its ramp.
void setTimeFunction(ParameterList& p, const std::string& functionDoc) {
  p.set("Function", "ramp", functionDoc, choices({"ramp", "constant", "table"}));
  p.set("Start Time", 0.0, "ramp: 0 until this time, then linear to 1 at Stop Time");
  p.set("Stop Time", 0.0,
        "ramp: the time it reaches 1 and holds from then on, in (Start Time, End Time]; 0: "
        "the load's End Time (e.g. press over [0, 0.5], then shift with Start Time 0.5)");
  p.set("Times", Teuchos::Array<double>(),
        "table: times t_i, strictly increasing (e.g. [0, 1, 2])");
  p.set("Factors", Teuchos::Array<double>(),
        "table: the factor at each of Times (e.g. [0, 1, 0]: up, then back down), linear "
        "between them, the first before and the last after them");
}

ParameterList dirichletItem() {
  ParameterList p;
  p.set("Group", "", "Boundary physical group whose nodes are constrained");
  p.set("Components", "xyz",
        "Constrained components: any of x, y, z (e.g. 'y', 'xy'); 'xyz' constrains all (x and "
        "y in 2D, where z alone is refused)",
        choices({"x", "y", "z", "xy", "xz", "yz", "xyz"}));
  p.set("Value", 0.0, "Prescribed displacement at the end of the load");
  setTimeFunction(p,
                  "Time scaling: 'ramp' = Value * (t - Start Time) / (Stop Time - Start Time) "
                  "between Start Time and Stop Time (0 before, Value after), 'constant' = Value "
                  "at every step, 'table' = Value * the factor interpolated in Times, Factors");
  return p;
}

ParameterList symmetryItem() {
  ParameterList p;
  p.set("Group", "",
        "Boundary physical group on a plane (a line in 2D): its nodes keep n . u = 0 and slide "
        "freely in it (a roller), and a contact point on it has no friction along n (zero by "
        "symmetry; a plain Dirichlet condition does not say that, so declare a cut here)");
  p.set("Normal", Teuchos::Array<double>(3, 0.0),
        "Normal of the plane (any length, either sense); [0, 0, 0] fits it through the group's "
        "nodes. The group must lie on the plane (within 1e-6 of its extent). A plane normal to "
        "an axis is the Dirichlet condition u_axis = 0; an inclined one is eliminated exactly, "
        "one dependent component per node, and the tangent stays symmetric");
  return p;
}

ParameterList tieItem() {
  ParameterList p;
  p.set("Groups", Teuchos::Array<std::string>(),
        "Two or more node groups (boundary physical groups or Point Groups) whose nodes are "
        "tied: for each component and each matched tuple of nodes, sum_i a_i u(node_i) = "
        "Value * Function(t). "
        "Groups of one node tie those nodes; groups of several (the same count in each) are "
        "matched by the translation between their centroids (a coincident interface, periodic "
        "faces). A tied node may lie on an inclined symmetry plane (Symmetry): the plane's "
        "equation is eliminated with the ties'");
  p.set("Coefficients", Teuchos::Array<double>(),
        "The a_i, one per group (code_aster's COEF_MULT, Abaqus' *EQUATION coefficients); "
        "empty means [1, -1]: the second group's nodes move with the first's");
  p.set("Components", "xyz",
        "Components tied, each with its own equation: any of x, y, z (e.g. 'y', 'xy'); 'xyz' "
        "means all (x and y in 2D, where z alone is refused)",
        choices({"x", "y", "z", "xy", "xz", "yz", "xyz"}));
  p.set("Value", 0.0,
        "The right side of every equation at the end of the load (code_aster's COEF_IMPO): 0 "
        "ties the nodes; otherwise it prescribes their relative motion (e.g. Coefficients "
        "[1, -1], Value 0.1: the first group's nodes 0.1 ahead of the second's). A tie with a "
        "right side must leave a dof to make dependent in each equation: not every dof "
        "prescribed, not implied by other ties");
  setTimeFunction(p,
                  "Time scaling of Value, as a Dirichlet condition's: 'ramp' (the default), "
                  "'constant' or 'table'");
  return p;
}

ParameterList springItem() {
  ParameterList p;
  p.set("Group", "",
        "Boundary physical group (or Point Group) whose nodes are each tied to ground by a "
        "spring");
  p.set("Components", "xyz",
        "Components the springs act in: any of x, y, z (e.g. 'y', 'xy'); 'xyz' means all (x "
        "and y in 2D, where z alone is refused). For a different stiffness per component, give "
        "one entry per component",
        choices({"x", "y", "z", "xy", "xz", "yz", "xyz"}));
  p.set("Stiffness", 0.0,
        "Stiffness k > 0 of each node's spring in each component (force per unit length): "
        "the node feels -k u, so the group's total stiffness is k times its node count");
  return p;
}

ParameterList pointGroupItem() {
  ParameterList p;
  p.set("Point", Teuchos::Array<double>(3, 0.0),
        "Location; the group is the one mesh node of an element closest to it");
  p.set("Tolerance", 1e-6,
        "Largest distance allowed between Point and that node (> 0, length units): a farther "
        "node is refused");
  return p;
}

ParameterList loadItem() {
  ParameterList p;
  p.set("Type", "pressure",
        "'pressure' (Value, against the outward normal of Group's facets), 'traction' (Vector "
        "per unit area on Group's facets), 'body-force' (Vector per unit volume in Block), "
        "'centrifugal' (Density * Angular Velocity^2 * r per unit volume in Block, r the "
        "distance vector from the spin axis) or 'point-load' (Vector, a force on Group's "
        "nodes, see Distribution)",
        choices({"pressure", "traction", "body-force", "centrifugal", "point-load"}));
  p.set("Group", "",
        "Boundary physical group (pressure, traction, point-load; point-load also takes a "
        "Point Group)");
  p.set("Block", "", "Element block (body-force, centrifugal); empty means every block");
  p.set("Density", 0.0,
        "centrifugal: mass density of the spinning block (> 0, mass per unit reference "
        "volume; the material's density is the slow-dynamics mass and is not used here)");
  p.set("Angular Velocity", 0.0,
        "centrifugal: spin rate omega in radians per unit time at the end of the load; the "
        "force, rho omega^2 r, is scaled by Function");
  p.set("Centre", Teuchos::Array<double>(3, 0.0),
        "centrifugal: a point of the spin axis (2D: the centre of rotation in the plane; "
        "axisymmetric: its x must be 0)");
  p.set("Axis", Teuchos::Array<double>({0.0, 0.0, 1.0}),
        "centrifugal: direction of the spin axis (3D; a plane 2D model spins about z, an "
        "axisymmetric one about its axis y)");
  p.set("Value", 0.0, "Pressure at the end of the load (pressure)");
  p.set("Follower", "automatic",
        "pressure: 'true' makes it follow the deformation (p on the current facets, "
        "-p n da by Nanson's formula, its load stiffness in the tangent, which is then not "
        "symmetric: the linear solver must take any matrix), for finite-strain blocks only; "
        "'false' keeps it on the reference facets (a dead load); 'automatic' follows on "
        "finite-strain blocks and not on small-strain ones. centrifugal: 'true' takes r at "
        "the current position (its load stiffness -rho omega^2 M is symmetric), 'false' at "
        "the reference position (a dead load), 'automatic' follows on finite-strain blocks. "
        "Tractions and body forces are dead loads",
        choices({"automatic", "true", "false"}));
  p.set("Vector", Teuchos::Array<double>(3, 0.0),
        "Force per unit area (traction), per unit volume (body-force) or force (point-load) at "
        "the end of the load");
  p.set("Distribution", "total",
        "point-load: 'total' (Vector is the group's total force, shared equally by its nodes) "
        "or 'per-node' (every node gets Vector)",
        choices({"total", "per-node"}));
  setTimeFunction(p, "Time scaling: 'ramp', 'constant' or 'table' (see Dirichlet)");
  return p;
}

ParameterList temperatureItem() {
  ParameterList p;
  p.set("Value", 20.0,
        "Temperature of the whole block, in degC, when Function is 1; the block is at its "
        "material's Reference Temperature T_ref (stress-free) when Function is 0: "
        "T(t) = T_ref + (Value - T_ref) f(t)");
  setTimeFunction(p,
                  "Time scaling of Value - T_ref: 'ramp' (heating from T_ref over the ramp), "
                  "'constant' (at Value from the first step) or 'table' (e.g. Times [0, 1, 2], "
                  "Factors [0, 0, 1]: T_ref during a first stage, heated during the second)");
  return p;
}

ParameterList probeItem() {
  ParameterList p;
  p.set("Point", Teuchos::Array<double>(3, 0.0),
        "Location; the probe reads the mesh node closest to it (reported with its distance)");
  p.set("Field", "displacement",
        "'displacement' (vector) or 'stress' (6 Voigt components, nodal average of element "
        "averages)",
        choices({"displacement", "stress"}));
  return p;
}

ParameterList profileItem() {
  ParameterList p;
  p.set("From", Teuchos::Array<double>(3, 0.0), "Start of the segment");
  p.set("To", Teuchos::Array<double>(3, 0.0), "End of the segment");
  p.set("Points", 21,
        "Evenly spaced points from From to To (>= 2); each reads the mesh node closest to it "
        "(its coordinates and distance are in the file)");
  p.set("Field", "stress",
        "'stress' (6 components, nodal average of element averages, as Probes) or "
        "'displacement'",
        choices({"stress", "displacement"}));
  p.set("Frame", "cartesian",
        "Components in the mesh's axes ('cartesian'; in axisymmetry x = r, y axial, zz the "
        "hoop stress) or 'cylindrical' about Axis through Centre (r from the axis, t = "
        "Axis x r, z along it: stress rr tt zz rt tz rz, e.g. a 3D tube's hoop stress tt; "
        "2D plane models about z)",
        choices({"cartesian", "cylindrical"}));
  p.set("Centre", Teuchos::Array<double>(3, 0.0), "Frame: cylindrical: a point of the axis");
  p.set("Axis", Teuchos::Array<double>({0.0, 0.0, 1.0}), "Frame: cylindrical: the axis direction");
  return p;
}

ParameterList obstacleItem() {
  ParameterList p;
  p.set("Type", "plane",
        "Rigid analytic master: 'plane', 'sphere' (a circle in 2D) or 'cylinder' (axis z in 2D)",
        choices({"plane", "sphere", "cylinder"}));
  p.set("Point", Teuchos::Array<double>(3, 0.0),
        "plane: a point on it; sphere: its centre; cylinder: a point on its axis");
  p.set("Normal", Teuchos::Array<double>(3, 0.0), "plane: normal pointing towards the body");
  p.set("Axis", Teuchos::Array<double>({0.0, 0.0, 1.0}), "cylinder: axis direction");
  p.set("Radius", 0.0, "sphere, cylinder: radius (> 0)");
  p.set("Side", "outside",
        "sphere, cylinder: where the body is, 'outside' (an indenter) or 'inside' (a hole)",
        choices({"outside", "inside"}));
  p.set("Displacement", Teuchos::Array<double>(3, 0.0),
        "Rigid translation of the obstacle at the end of the load");
  setTimeFunction(p, "Time scaling of Displacement: 'ramp', 'constant' or 'table'");
  return p;
}

// A contact zone; `user` (may be null) picks the formulation type and says whether an obstacle
// is given (its sublist is only valid when present).
ParameterList contactItem(const ParameterList* user, const std::string& where,
                          const std::string& path) {
  ParameterList p;
  p.set("Slave", "",
        "Boundary physical group whose nodes are the contact points (prefer the finer mesh)");
  p.set("Master", "",
        "Boundary physical group of the other body; leave empty when an Obstacle is given");
  if (!user || user->isSublist("Obstacle")) p.set("Obstacle", obstacleItem());
  p.set("Friction", 0.0, "Coulomb coefficient mu >= 0; 0 builds no friction unknowns");
  p.set("No Friction Group", "",
        "Boundary group of slave nodes without friction (code_aster's SANS_GROUP_NO_FR); not "
        "needed where the Dirichlet conditions fix a node's tangential motion: that friction "
        "direction is dropped automatically (doc/scenes.md)");
  p.set("No Contact Group", "",
        "Boundary group of slave nodes left out of the zone: always open, no contact force "
        "(code_aster's SANS_GROUP_NO); not needed where the Dirichlet conditions hold a slave "
        "node and its master in every direction: such a node is opened automatically");
  p.set("Search Distance", 0.0,
        "Master points farther than this from a slave point are ignored; 0 = twice the largest "
        "slave facet");
  p.set("Initial Contact", "interpenetrated",
        "Statuses the first load step starts from (Code_Aster's CONTACT_INIT): "
        "'interpenetrated' (those the predictor gives: closed where the gap is <= 0), 'all' "
        "(every paired point closed), 'none' (every point open), by the initial multipliers "
        "(formulations with multipliers only): a starting point, which changes the answer only "
        "where it is not unique (doc/algorithms.md)",
        choices({"interpenetrated", "all", "none"}));
  std::vector<std::string> discretizations = {"automatic"};
  for (const auto& name : contactDiscretizationRegistry().names())
    discretizations.push_back(name);
  p.set("Discretization", "automatic",
        "Where the contact conditions hold (one of: automatic, " +
            contactDiscretizationRegistry().joinedNames() +
            "; `contactlab list discretization`). 'automatic' takes mortar on tri6 and quad8 slave "
            "facets (tet10 and hex20 bodies), whose corners carry no share of a smooth pressure "
            "so that collocation at the slave nodes is not sound there, but for the normal-field "
            "formulation, which mortar does not pair; node-to-segment otherwise. node-to-segment: "
            "a slave node beyond a free edge of the master surface, by more than 5 % of the "
            "edge's facet, faces no master and is open. mortar: each slave facet against the "
            "master surface nearest to it that faces it; its geometry is a fixed point "
            "(doc/verification.md)",
        choices(discretizations));
  p.set("Multiplier Basis", "dual",
        "mortar: the multiplier basis, 'dual' (biorthogonal to the slave's shape functions, "
        "built on the covered part of each facet: nodal pressures like lumped ones) or "
        "'standard' (the shape functions themselves: its nodal values overshoot at the "
        "contact edge and amplify the bulk's nodal-force noise, doc/verification.md); on "
        "tri6 and quad8 facets both are built on transformed shape functions whose corner "
        "integrals are positive",
        choices({"standard", "dual"}));
  p.set("Formulation", typedSection(formulationRegistry(), userSublist(user, "Formulation"),
                                    "augmented-lagrangian", where, path + "/Formulation"));
  return p;
}

// A block's material (typed by the material registry) and how its elements form the strain.
ParameterList materialItem(const ParameterList& user, const std::string& where,
                           const std::string& path) {
  ParameterList item = typedSection(materialRegistry(), &user, "linear-elastic", where, path);
  std::vector<std::string> technologies = {"automatic"};
  for (const auto& name : elementTechnologyRegistry().names())
    technologies.push_back(name);
  item.set("Element Technology", "automatic",
           "How the block's elements form the strain their material sees (one of: automatic, " +
               elementTechnologyRegistry().joinedNames() +
               "). 'automatic' takes a locking-free one where the volume barely changes "
               "(plastic flow, or nu >= 0.45): b-bar on quad4/hex8 in small strain, mixed-up "
               "otherwise; and full integration elsewhere (plane "
               "stress, tri3/tet4, compressible elastic laws). doc/scenes.md, 'Element "
               "technology'",
           choices(technologies));
  return item;
}

ParameterList geometrySection() {
  ParameterList p("Geometry");
  p.set("Type", "plane-strain",
        "What a 2D mesh stands for: 'plane-strain' (a slice of unit thickness, out-of-plane "
        "strains zero; ignored in 3D), 'plane-stress' (a thin plate of unit thickness loaded "
        "in its plane, sigma_zz = 0, as Abaqus CPS and code_aster C_PLAN; every material law, "
        "its thickness strain solved at each point; forces per unit reference thickness; "
        "pressures dead (Follower: false); 2D only) or 'axisymmetric' (the solid of "
        "revolution about the y "
        "axis: x = r >= 0 the radius, y the axial coordinate, as Abaqus CAX and code_aster "
        "AXIS; small- and finite-strain materials, a pressure on a finite-strain block "
        "following the current ring as in 2D and 3D; the zz "
        "stress is the hoop stress sigma_tt; every "
        "force, reaction, spring and point load is per full 360 degree ring, so a point load "
        "is a ring load; nodes on the axis need a Dirichlet condition on x; doc/scenes.md)",
        choices({"plane-strain", "plane-stress", "axisymmetric"}));
  return p;
}

ParameterList initialStateSection() {
  ParameterList p("Initial State");
  p.set("From", "",
        "A folder of an earlier run (its checkpoint.h5, written after each converged step): "
        "this run starts from that run's last converged state (displacements, contact "
        "multipliers and friction history, the internal variables of every element) instead "
        "of rest. The mesh must be the same (node and element ids are checked); a relative "
        "path is taken from the current directory, like Output/Directory; empty: start "
        "from rest");
  p.set("Time", "continue",
        "With From: 'continue' starts at the checkpoint's load time and step number and runs "
        "to Load Steps/End Time in its nominal steps (End Time / Steps, or Times; the loads keep "
        "their time functions, with this scene's End Time: a chain equals one long run when "
        "they do not depend on it, e.g. tables); 'zero' starts the load time and the step count "
        "at 0 (a new load history on the earlier state)",
        choices({"continue", "zero"}));
  return p;
}

ParameterList outputSection(const ParameterList* user, const std::string& where) {
  ParameterList p("Output");
  p.set("Directory", "",
        "Results folder; empty means results/<scene name> (the --out option overrides it)");
  p.set("VTK", true,
        "Write result.pvd and one .vtu (.pvtu on several ranks) per frame: a rest frame at "
        "t = 0 (the undeformed state, every contact point free), then one per converged step; "
        "a point field node_id holds each node's id (contact.csv's node column)");
  p.set("Checkpoint Every", 1,
        "Write checkpoint.h5 (the state a run continues from: Initial State/From, "
        "`contactlab run --restart`) after every this many converged steps and after the "
        "last (>= 0; 0: never)");
  p.set("Contact Times", Teuchos::Array<double>(),
        "Load times (increasing, in (0, End Time]) after whose converged step the contact "
        "points are also written to contact_t<time>.csv (contact.csv's columns), e.g. the end "
        "of each stage of a load history; the steps land on them; a time the run does not "
        "reach (it failed before) is reported at the end of the run");
  p.set("Critical Mu Check", false,
        "After each converged step, the uniqueness check of `contactlab critical-mu` (status "
        "patterns around the state, determinant signs, critical mu): a warning when mu >= "
        "mu_crit or the signs differ, and a critical_mu column in steps.csv");
  p.set("Critical Mu Tolerance", 1e-6,
        "Uniqueness check (critical-mu and Critical Mu Check): a contact point is ambiguous, "
        "and takes each adjacent status, when its contact indicator is within this fraction of "
        "the largest one, or its friction indicator within this of the friction ball's edge "
        "([0, 1))");
  p.set("Critical Mu Max Patterns", 64,
        "Uniqueness check: every combination of the ambiguous points' statuses is examined when "
        "there are at most this many; beyond, the converged pattern and single changes of one "
        "ambiguous point, up to this many (>= 1)");
  p.set("Probes",
        namedSection(userSublist(user, "Probes"), "Output/Probes", where,
                     [](const ParameterList&, const std::string&) { return probeItem(); }));
  p.set("Profiles",
        namedSection(userSublist(user, "Profiles"), "Output/Profiles", where,
                     [](const ParameterList&, const std::string&) { return profileItem(); }));
  return p;
}

}  // namespace

void registerAll() {
  registerMeshSources();
  registerMaterials();
  registerElementTechnologies();
  registerLinearSolvers();
  registerFormulations();
  registerContactDiscretizations();
}

ParameterList sceneSchema(const ParameterList& scene, const std::string& where) {
  ParameterList valid("contactlab");
  valid.set("Name", "", "Scene name, used for the default results folder");
  valid.set("Description", "", "Free text, copied to summary.json");
  valid.set("Mesh", typedSection(meshSourceRegistry(), userSublist(&scene, "Mesh"), "rectangle",
                                 where, "Mesh"));
  valid.set("Geometry", geometrySection());
  valid.set("Point Groups", namedSection(userSublist(&scene, "Point Groups"), "Point Groups", where,
                                         [](const ParameterList&, const std::string&) {
                                           return pointGroupItem();
                                         }));
  valid.set("Materials", namedSection(userSublist(&scene, "Materials"), "Materials", where,
                                      [&](const ParameterList& user, const std::string& path) {
                                        return materialItem(user, where, path);
                                      }));
  valid.set("Dirichlet",
            namedSection(userSublist(&scene, "Dirichlet"), "Dirichlet", where,
                         [](const ParameterList&, const std::string&) { return dirichletItem(); }));
  valid.set("Symmetry",
            namedSection(userSublist(&scene, "Symmetry"), "Symmetry", where,
                         [](const ParameterList&, const std::string&) { return symmetryItem(); }));
  valid.set("Ties",
            namedSection(userSublist(&scene, "Ties"), "Ties", where,
                         [](const ParameterList&, const std::string&) { return tieItem(); }));
  valid.set("Springs",
            namedSection(userSublist(&scene, "Springs"), "Springs", where,
                         [](const ParameterList&, const std::string&) { return springItem(); }));
  valid.set("Loads",
            namedSection(userSublist(&scene, "Loads"), "Loads", where,
                         [](const ParameterList&, const std::string&) { return loadItem(); }));
  valid.set("Temperature", namedSection(userSublist(&scene, "Temperature"), "Temperature", where,
                                        [](const ParameterList&, const std::string&) {
                                          return temperatureItem();
                                        }));
  valid.set("Contact", namedSection(userSublist(&scene, "Contact"), "Contact", where,
                                    [&](const ParameterList& user, const std::string& path) {
                                      return contactItem(&user, where, path);
                                    }));
  valid.set("Load Steps", *StaticSolverOptions::validLoadSteps());
  valid.set("Newton", *StaticSolverOptions::validNewton());
  valid.set("Algorithm", *StaticSolverOptions::validAlgorithm());
  valid.set("Linear Solver",
            typedSection(linearSolverRegistry(), userSublist(&scene, "Linear Solver"), "mumps",
                         where, "Linear Solver"));
  valid.set("Initial State", initialStateSection());
  valid.set("Output", outputSection(userSublist(&scene, "Output"), where));
  return valid;
}

void validateScene(ParameterList& scene, const std::string& where) {
  const ParameterList valid = sceneSchema(scene, where);
  validateAndSetDefaults(scene, valid, where);
  if (scene.sublist("Materials").numParams() == 0)
    throw InputError(where +
                     ": Materials is empty; give one sublist per element block, e.g. "
                     "Materials: {body: {Type: linear-elastic, linear-elastic: {E: 1, "
                     "nu: 0.3}}}");
}

std::vector<SceneSection> sceneSections() {
  std::vector<SceneSection> sections{
      {"Geometry", "", geometrySection()},
      {"Point Groups/<name>", "", pointGroupItem()},
      {"Dirichlet/<name>", "", dirichletItem()},
      {"Symmetry/<name>", "", symmetryItem()},
      {"Ties/<name>", "", tieItem()},
      {"Springs/<name>", "", springItem()},
      {"Loads/<name>", "", loadItem()},
      {"Temperature/<block>", "", temperatureItem()},
      {"Contact/<zone>", "", contactItem(nullptr, "", "Contact/<zone>")},
      {"Contact/<zone>/Obstacle", "", obstacleItem()},
      {"Load Steps", "", *StaticSolverOptions::validLoadSteps()},
      {"Newton", "", *StaticSolverOptions::validNewton()},
      {"Algorithm", "", *StaticSolverOptions::validAlgorithm()},
      {"Algorithm/slow-dynamics", "",
       StaticSolverOptions::validAlgorithm()->sublist("slow-dynamics")},
      {"Initial State", "", initialStateSection()},
      {"Output", "", outputSection(nullptr, "")},
      {"Output/Probes/<name>", "", probeItem()},
      {"Output/Profiles/<name>",
       "A field along a segment, written after every converged step to profile_<name>.csv (the "
       "last converged step) and, at each Output/Contact Times entry, to "
       "profile_<name>_t<time>.csv: columns time, s (the point's distance from From), the "
       "point, the node read, its distance, then the components.",
       profileItem()}};
  return sections;
}

}  // namespace contactlab
