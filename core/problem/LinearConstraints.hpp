#pragma once
// Dofs eliminated by linear constraints: symmetry (roller) conditions n . u = 0 on planes that
// are not normal to an axis, and ties between the dofs of nodes (TieCondition,
// TieEquations.hpp), whose right side g(t) may be nonzero. Each dependent dof k is written in
// independent ones, u_k = sum_j c_kj u_j + b_k(t), so u = T v + b(t) with v the independent
// dofs; b is nonzero only on the dependents of ties with a right side. A symmetry plane makes one
// component per node dependent (two where a node lies on two planes in 3D), on the node's
// other components; a tie's equation one dof, on the other nodes' dofs.
//
// The system solved is T^T K T v = -T^T R, which stays symmetric when K is: reduce() combines
// the dependent rows and columns of an assembled tangent into their partners' and leaves a unit
// row and column in their place (zero residual there, like a Dirichlet dof). impose(t) writes
// the dependent components of a state from the others with b(t), as the Dirichlet values are
// set at a step's start (Problem::applyDirichlet); project() writes those of an increment
// without b, after each linear solve (NonlinearSystem::completeIncrement): every iterate then
// satisfies the constraints exactly and the Newton step is the constrained problem's own.
//
// A tie's dependent moves its row and column to other nodes: the matrix graph must hold them
// (partnerNodes: MatrixAssembler widens each element holding a dependent node; partnerDofs:
// ContactAssembler each contact point), and the rows must be on one rank (DofMap owns the
// linked nodes together).
//
// Planes normal to an axis are Dirichlet conditions (u_axis = 0): resolveSymmetryConditions
// turns them into those, so the contact code drops a friction direction they fix as it does for
// any Dirichlet condition.
#include "base/LinearAlgebra.hpp"
#include "core/problem/SolidModel.hpp"
#include "core/problem/TieEquations.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace contactlab {

class DofMap;

// The plane of a symmetry condition: its unit normal, checked (or fitted, when the given normal
// is zero) against the group's nodes, which must lie on one plane (within 1e-6 of the group's
// extent). Throws InputError with a sentence otherwise.
std::array<double, 3> symmetryPlaneNormal(const Mesh& mesh, const SymmetryCondition& condition);

// Resolves every model.symmetries' normal; those normal to an axis become Dirichlet conditions
// (value 0, constant) and leave the list. Throws InputError for a plane that is not one.
void resolveSymmetryConditions(SolidModel& model);

class LinearConstraints {
 public:
  // `model`: symmetries resolved (inclined only); `ties`: tieEquations(model), whose linked
  // nodes `dofs` owns together. A component a Dirichlet condition fixes is never dependent (its
  // value enters project() as given); where the planes leave no free component to eliminate,
  // the Dirichlet conditions hold the node. Every rank knows every node's dependents: a row may
  // have columns of another rank's symmetry nodes. At a tied node the planes' equations join the
  // ties' in one elimination (their reactions then from the equations' multipliers). Throws
  // InputError for a tied node without an element.
  LinearConstraints(const SolidModel& model, const DofMap& dofs,
                    const std::vector<TieEquation>& ties = {});

  // No rank has a dependent dof (collective value).
  bool empty() const { return !anywhere_; }
  // Mesh nodes a tie joins (sorted), and for a node with a tie's dependent dof the other nodes
  // its row and column move to (empty: none).
  const std::vector<std::int64_t>& tiedNodes() const { return tiedNodes_; }
  std::vector<std::int64_t> partnerNodes(std::int64_t node) const;
  // For a dependent dof (global id), the free dofs its row and column move to; empty for any
  // other dof. Every rank answers for every dof.
  std::vector<GO> partnerDofs(GO gid) const;
  // Nodes (mesh indices) that carry an inclined symmetry condition (every rank's).
  const std::vector<std::int64_t>& nodes() const { return nodes_; }
  // The unit normals of the inclined planes through a mesh node (empty: none).
  std::vector<std::array<double, 3>> planeNormals(std::int64_t node) const;
  // The unit normals of every symmetry plane through a mesh node: the inclined ones and those
  // imposed as Dirichlet conditions (model.axisSymmetries).
  std::vector<std::array<double, 3>> allPlaneNormals(std::int64_t node) const;

  // u_k = sum_j c_kj u_j on this rank's dependent components (an increment). `owned`: an owned
  // vector whose first entries are the solid's owned dofs (the solid's or the contact
  // problem's).
  void project(double* owned) const;
  // u_k = sum_j c_kj u_j + b_k(t): a state at time t, the ties' right sides included.
  void impose(double t, double* owned) const;
  // T^T K T on a fill-complete matrix whose first rows are the solid's owned dofs and whose
  // displacement columns carry the solid's global dof ids, T^T R on a residual shaped alike
  // (either may be null). Collective when a matrix is given.
  void reduce(Matrix* tangent, Vector* residual) const;
  // The reaction of each condition, as a Dirichlet condition's: R summed over its nodes'
  // components, from a residual before reduce() (owned entries; collective). A node on several
  // planes splits its force along their normals (at equilibrium it lies in their span).
  std::vector<std::array<double, 3>> reactions(const Vector& residual) const;
  // The force each tie exerts on the nodes of its first group (summed, per component), from a
  // residual before reduce() (owned entries; collective): the equations' multipliers mu solve
  // A_D^T mu = R_D on the dependent dofs D, and the force is sum_e mu_e a_e,first.
  std::vector<std::array<double, 3>> tieForces(const Vector& residual) const;

 private:
  struct Term {
    LO lid;           // owned LID of an independent component (-1: another rank's node)
    GO gid;           // its global dof id
    double c;         // u_k += c u_j
    bool prescribed;  // fixed by a Dirichlet condition: in project() only
  };
  struct Dependent {
    LO lid;  // owned LID (-1: another rank's node)
    GO gid;
    std::vector<Term> terms;
    // b_k(t) = sum of weight * (the tie's function at t), by model.ties index (empty: 0).
    std::vector<std::pair<int, double>> rightSide;
  };
  struct OwnedNode {
    LO firstLid;                                                // LID of component 0
    std::vector<std::pair<int, std::array<double, 3>>> planes;  // (condition, unit normal)
  };
  // The dependents of `equations`: the inclined planes' at tied nodes, then the ties'. Throws
  // InputError for a tie with a right side whose equation is prescribed or implied.
  void addTies(const SolidModel& model, const DofMap& dofs,
               const std::vector<TieEquation>& equations, const std::set<MeshDof>& fixed);

  int dim_;
  std::vector<Dependent> all_;
  std::vector<OwnedNode> ownedNodes_;
  std::vector<std::int64_t> nodes_;                                        // sorted
  std::vector<std::int64_t> tiedNodes_;                                    // sorted
  std::map<std::int64_t, std::vector<std::int64_t>> partners_;             // by dependent node
  std::map<GO, std::size_t> dependentOf_;                                  // all_'s entry by gid
  std::vector<std::vector<std::array<double, 3>>> normals_;                // per nodes_ entry
  std::map<std::int64_t, std::vector<std::array<double, 3>>> axisPlanes_;  // by mesh node
  std::size_t numConditions_ = 0;
  struct TieForceTerm {
    LO lid;   // an owned dependent dof
    int tie;  // model.ties index
    int component;
    double w;  // the force's component += w R(lid)
  };
  std::vector<TieForceTerm> tieForceTerms_;
  struct PlaneForceTerm {
    LO lid;         // an owned dependent dof
    int condition;  // model.symmetries index
    double w;       // the condition's force += w R(lid) times its normal
  };
  std::vector<PlaneForceTerm> planeForceTerms_;
  std::vector<std::array<double, 3>> conditionNormals_;  // by model.symmetries index
  std::vector<LoadFunction> tieFunctions_;               // by model.ties index
  std::size_t numTies_ = 0;
  int anywhere_ = 0;
  Teuchos::RCP<const Comm> comm_;
};

}  // namespace contactlab
