#pragma once
// The discrete solid problem on Tpetra: partition, dof maps, matrix graph (built once), and
// assembly of the residual R(u, t) = f_int(u) - f_ext(u, t) and its tangent K = dR/du.
//
// Dirichlet conditions are imposed by setting the prescribed values in u (applyDirichlet)
// and eliminating the constrained dofs element by element: their rows and columns of K are
// zero but for a unit diagonal and their residual entries are zero, so K stays symmetric when
// the element matrices are (a follower pressure's load stiffness is not) and a Newton increment
// never changes a prescribed value. The residual a constrained dof would have carried is kept
// as the reaction of its condition. Springs to ground add k u to the residual and k to the
// diagonal of the tangent at their nodes (NodalAssembler.hpp). Symmetry conditions on inclined
// planes eliminate one component per node from the others, ties one dof per equation from the
// other nodes' (LinearConstraints.hpp); symmetry planes normal to an axis are Dirichlet
// conditions. External forces depend on u only
// through follower pressures on finite-strain elements (SurfaceLoadAssembler.hpp).
#include "base/LinearAlgebra.hpp"
#include "core/io/MeshPiece.hpp"
#include "core/problem/CentrifugalLoadKernel.hpp"
#include "core/problem/DofMap.hpp"
#include "core/problem/ElementTechnology.hpp"
#include "core/problem/NonlinearSystem.hpp"
#include "core/problem/SolidModel.hpp"

#include <Teuchos_RCP.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace contactlab {

class MassKernel;
class MatrixAssembler;
class ElementKernel;
class NodalAssembler;
class SurfaceLoadAssembler;
class LinearConstraints;

// Errors of a displacement field against an exact one (manufactured solutions, studies).
struct DisplacementErrors {
  double l2 = 0;       // ||u_h - u||_L2
  double energy = 0;   // |u_h - u|_H1 (seminorm: the energy-norm rate)
  double l2Exact = 0;  // ||u||_L2, for relative errors
  double energyExact = 0;
};

// Fields at the mesh nodes (Problem::nodalFields).
struct NodalFields {
  std::vector<double> stress;         // 6 per node, Cauchy, Voigt order xx yy zz xy yz xz
  std::vector<double> vonMises;       // 1 per node, of the node's (averaged) stress
  std::vector<double> plasticStrain;  // 1 per node; empty without internal variables
};

// The internal variables' state over the model (collective), for summary.json.
struct MaterialStateSummary {
  bool plasticity = false;           // some block's material has internal variables
  double maxPlasticStrain = 0;       // largest equivalent plastic strain at a point
  double plasticVolumeFraction = 0;  // reference volume where it is > 0, over the total
};

// The converged internal variables of every element, in global element order (block by block,
// cell by cell, as Mesh::blocks lists them): element k's values are
// values[offsets[k] .. offsets[k + 1]), its quadrature points' states one after the other
// (empty for a material without internal variables). Checkpoints carry them (apps/RunCheckpoint).
struct ElementStates {
  std::vector<std::int64_t> offsets;  // numElements + 1
  std::vector<double> values;
};

struct Reaction {
  std::string name;               // the Dirichlet condition's (or spring's) name
  std::array<double, 3> force{};  // sum of reactions over its nodes (global)
};

// Every element block of the model's mesh has a material and every material names a block;
// throws InputError naming the block (and the mesh's blocks) otherwise.
void checkBlockMaterials(const SolidModel& model);

class Problem : public NonlinearSystem {
 public:
  // Partitions the mesh, builds the maps and the matrix graph, and checks the model: every
  // block has a material, every group named by a condition exists, no element is inverted.
  // Throws InputError with a sentence naming what is wrong.
  Problem(SolidModel model, const Teuchos::RCP<const Comm>& comm);
  ~Problem() override;

  const SolidModel& model() const { return model_; }
  const DofMap& dofs() const { return *dofs_; }
  int dim() const { return dofs_->dim(); }

  Teuchos::RCP<Vector> createVector() const override;
  // The tangent matrix (owned rows), refilled by every assemble() with a tangent.
  const Teuchos::RCP<Matrix>& tangent() const override;

  // Sets the prescribed values at time t in u (owned entries), and the dofs an inclined
  // symmetry plane or a tie makes dependent (with the ties' right sides at t).
  void applyDirichlet(double t, Vector& u) const override;
  // Writes the dependent components of an increment from the others (LinearConstraints).
  void completeIncrement(Vector& dx) const override;
  // Twice the largest distance of a node from the nodes' centroid (every rank holds the whole
  // mesh).
  double modelSize() const override;
  // Assembles R(u, t) into `residual` (if not null) and K(u) into tangent() when requested.
  void assemble(const Vector& u, double t, Vector* residual, bool withTangent) override;
  AssemblyFailure assemblyFailure() const override { return assemblyFailure_; }
  // Collective (an export and a reduction the first time after an assembly).
  double internalForceNorm() const override;
  // Reactions of the Dirichlet conditions (those of the symmetry planes normal to an axis
  // among them), then of the inclined symmetry planes, then the force each tie exerts on its
  // first group's nodes, at the last assemble() with a residual,
  // plus what addToReactions added since (the contact forces at supported nodes).
  const std::vector<Reaction>& reactions() const { return reactions_; }
  // Adds forces that other terms put on the constrained dofs (contact's, shaped as an owned
  // displacement vector) to the reactions of the last assembly (collective).
  void addToReactions(const Vector& forces);
  // Force each spring exerts on the body (-sum k u over its nodes), at the same assembly.
  const std::vector<Reaction>& springForces() const { return springForces_; }
  // Internal variables: the last assembled (trial) state becomes the converged one.
  void commitState();
  void commitState(const Vector& /*u*/, double /*t*/) override { commitState(); }
  // Checkpoints (ProblemState.cpp): the state a run continues from, in mesh order so that a
  // checkpoint does not depend on the number of ranks. Collective; the whole of it on rank 0,
  // empty elsewhere. Displacements: numNodes() x dim in mesh node order (0 at nodes no element
  // uses).
  std::vector<double> gatherDisplacements(const Vector& u) const;
  ElementStates gatherElementStates() const;
  // Every rank passes the whole of it and takes its own part: u's owned entries, the converged
  // (and trial) internal variables of its elements. Throws InputError when a size does not match
  // this model.
  void scatterDisplacements(const std::vector<double>& all, Vector& u) const;
  void setElementStates(const ElementStates& states);
  // Empty when every material has a density; else a sentence naming the block without one.
  std::string massUnavailable() const override;
  // The inertia c M (u - reference) of a regularizing dynamics (NonlinearSystem.hpp), added
  // element by element. Throws InputError for a nonzero coefficient without a mass.
  void setInertia(const InertiaTerm& inertia) override;
  // The inclined symmetry planes' and the ties' elimination. A caller that adds terms to the
  // tangent and residual (the contact problem) defers it: assemble() then leaves both
  // unreduced, and the caller reduces its own monolithic system.
  const LinearConstraints& constraints() const { return *linearConstraints_; }
  void deferConstraintReduction() { deferConstraints_ = true; }
  // Dofs eliminated by Dirichlet conditions, indexed by overlap LID (owned dofs first).
  const std::vector<char>& constrainedDofs() const { return constrained_; }
  // Names of the pressure loads that follow the deformation (on finite-strain elements, see
  // SurfaceLoadAssembler.hpp), the same on every rank. Their load stiffness makes the tangent
  // unsymmetric: a linear solver that assumes symmetry must not solve it.
  const std::vector<std::string>& followerLoads() const;
  // Whether the solid's tangent is symmetric: every block's material tangent and element
  // technology keep it (f-bar does not), and no follower load.
  bool tangentSymmetric() const;
  // Each mesh block's element technology (in Mesh::blocks order), resolved at construction.
  const std::vector<BlockTechnology>& elementTechnologies() const { return blockTechnology_; }

  // This rank's elements and nodes with displacement, stress (cell average, Cauchy), von_mises,
  // material (block index) and rank, and with plasticity equivalent_plastic_strain (cell
  // average) and plastic (1 where the last converged step increased it), and with prescribed
  // temperatures a cell field temperature, for the writers.
  // Stresses at the block temperatures of time t (the time u converged at).
  MeshPiece outputPiece(const Vector& u, double t) const;
  // Nodal averages of the element averages over every element around a node (the cell fields
  // of outputPiece, smoothed), for every mesh node in mesh order, on rank 0 (empty on the
  // others; NaN at a node without elements). Collective.
  NodalFields nodalFields(const Vector& u, double t) const;
  MaterialStateSummary materialState() const;
  // Errors against an exact displacement u(x) and gradient du_i/dx_j (grad[i * 3 + j]),
  // integrated with a rule two degrees above the element's order (collective).
  DisplacementErrors displacementErrors(
      const Vector& u, const std::function<void(const double* x, double* u)>& exact,
      const std::function<void(const double* x, double* grad)>& exactGradient) const;
  // Displacement of a mesh node (collective; every rank gets the value).
  std::array<double, 3> nodeDisplacement(const Vector& u, std::int64_t meshNode) const;
  // Nodal average of the element-average Cauchy stress at a mesh node, at the block
  // temperatures of time t (collective).
  std::array<double, 6> nodeStress(const Vector& u, std::int64_t meshNode, double t) const;
  // The same at several mesh nodes, with one pass over the elements (collective).
  std::vector<std::array<double, 6>> nodeStresses(const Vector& u,
                                                  const std::vector<std::int64_t>& meshNodes,
                                                  double t) const;
  // The prescribed temperature of mesh block `block` at time t; empty when the scene gives
  // none (the material is then at its reference temperature).
  std::optional<double> blockTemperature(int block, double t) const;

 private:
  // The inclined planes' reactions and the ties' forces (their entries after the Dirichlet
  // conditions') from `forces`, a residual or forces added to it: set, or added to them.
  void constraintReactions(const Vector& forces, bool add);
  // One element of this rank: its overlap nodes and dofs, and its internal variables.
  struct LocalElement {
    int block;
    std::size_t cell;
    int kernel;              // index in kernels_
    std::vector<int> nodes;  // overlap node indices
    std::vector<LO> rows;    // overlap-map LIDs of its dofs
    std::vector<double> stateOld, stateNew;
    bool plastic = false;  // the last converged step increased the plastic strain somewhere
    // Small strain, a linear material (Material::linear) and no prescribed temperature: the
    // tangent never changes, so it is integrated at the first assembly and kept (`stiffness`,
    // rows.size() squared, row major), and the force is stiffness * u. Measured on the peers'
    // tet10 hemisphere (125 730 dofs, 9 Newton iterations): assembly 5.4 s -> 1.8 s.
    bool linear = false;
    std::vector<double> stiffness;
  };
  void checkModel() const;
  // The element's equivalent plastic strain, averaged over its points (converged state).
  double elementPlasticStrain(const LocalElement& e) const;
  ElementSetting elementSetting(int block) const;
  void checkElementGeometry() const;
  void gatherCoordinates(const std::vector<int>& overlapNodes, std::vector<double>& x) const;
  void buildGraph();
  // f += surface loads (follower pressures at the overlap displacement u) and body forces.
  void addExternalForces(double t, const double* u, std::vector<double>& f) const;
  // The centrifugal loads on element e at the overlap displacement u: f += forces (when not
  // nullptr), k += the follower loads' stiffness (when not nullptr).
  void addCentrifugal(const LocalElement& e, double t, const double* u, double* f, double* k) const;
  std::array<double, 6> elementStress(std::size_t e, const Vector& uOverlap, double t) const;
  Teuchos::RCP<Vector> overlapCopy(const Vector& u) const;

  SolidModel model_;
  Teuchos::RCP<const Comm> comm_;
  std::unique_ptr<DofMap> dofs_;
  std::vector<LocalElement> elements_;
  // Every element linear: the solid's tangent is the same at every assembly (assemble()).
  bool allLinear_ = false;
  std::vector<BlockTechnology> blockTechnology_;  // per mesh block
  // One per element type, kinematics and technology.
  std::vector<std::unique_ptr<ElementKernel>> kernels_;
  std::vector<std::unique_ptr<MassKernel>> massKernels_;  // same order
  std::vector<CentrifugalLoadKernel> centrifugal_;        // one per model_.centrifugalLoads
  // The inertia term of setInertia(), its reference on the overlap map.
  struct Inertia {
    double coefficient = 0;
    bool lumped = false;
    Teuchos::RCP<Vector> reference;
  } inertia_;
  std::vector<const Material*> blockMaterial_;
  std::vector<std::shared_ptr<const Material>> planeStressLaws_;  // the wrappers, if planeStress
  std::vector<const BlockTemperature*> blockTemperature_;         // per mesh block, nullptr: none
  // Dofs (overlap LIDs) constrained, and per owned constrained dof its condition.
  std::vector<char> constrained_;
  struct Constraint {
    int lid;        // owned LID
    int condition;  // index in model_.dirichlet
    int component;
    std::int64_t node;
  };
  std::vector<Constraint> constraints_;
  std::unique_ptr<LinearConstraints> linearConstraints_;
  bool deferConstraints_ = false;
  std::unique_ptr<SurfaceLoadAssembler> surfaceLoads_;
  std::unique_ptr<NodalAssembler> nodal_;  // springs and point loads
  std::unique_ptr<MatrixAssembler> assembler_;
  Teuchos::RCP<Export> exporter_;
  Teuchos::RCP<Import> importer_;
  std::vector<Reaction> reactions_, springForces_;
  AssemblyFailure assemblyFailure_;
  // The last residual assembly's internal forces on this rank's overlap dofs, and their summed
  // norm once asked for (negative until then): the export is paid once per request, not per
  // assembly.
  std::vector<double> internalForces_;
  mutable double internalForceNorm_ = -1;
};

}  // namespace contactlab
