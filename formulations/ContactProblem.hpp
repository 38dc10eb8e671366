#pragma once
// The solid problem plus contact zones, as one system R(x, t) = 0 on Tpetra: the short class that
// wires the contact pipeline's stages (in the spirit of LLNL Tribol):
//   pairing      ContactDiscretization (per zone, from its registry: node-to-segment, mortar,
//                rigid-obstacle) pairs each point on the current configuration and freezes its
//                geometry (master nodes and coefficients, normal, tangents);
//   kinematics   ContactPointKernel: gap and slip along the frozen geometry and their operators,
//   + law        the zone's ContactLaw, the element residual and tangent (and the geometry's
//                derivatives when the geometry is in Newton);
//   assembly     ContactAssembler: the graph and the insertion of the owned rows;
//   outputs      ContactPointResult / ContactPointFields.
// The points (ContactPoint) are plain data the stages fill, and every stage reads the replicated
// ContactSurfaceState. This class holds the layout of the unknowns and the algorithms' seam
// (ContactControls: fixed points, cycling treatments).
//
// Unknowns x = (u, m): the solid's displacements, then the multipliers of the formulations that
// have them (p and, with friction, Lambda at each slave point), one monolithic map whose owned
// part starts with the solid's owned dofs (same local indices), then the multipliers of the
// slave points whose node this rank owns. Each slave node is a contact point weighted by its
// tributary area (TributaryAreas.hpp, in the reference configuration).
//
// Parallel: contact surfaces are small. At every evaluation each rank imports the surface
// displacements and all multipliers (a replicated vector), evaluates every contact point (the
// same numbers on every rank, so pairings and statuses agree everywhere) and adds the rows it
// owns. The tangent's graph is the solid's plus the contact couplings and is rebuilt only when
// a pairing changes.
#include "core/io/MeshPiece.hpp"
#include "core/problem/NonlinearSystem.hpp"
#include "core/problem/Problem.hpp"
#include "formulations/ContactControls.hpp"
#include "formulations/ContactHistory.hpp"
#include "formulations/ContactPointFields.hpp"
#include "formulations/ContactPointResult.hpp"
#include "formulations/ContactZone.hpp"

#include <functional>
#include <memory>
#include <unordered_set>
#include <vector>

namespace contactlab {

class ContactAssembler;
class ContactDiscretization;
class ContactPointKernel;
class ContactSurfaceState;
struct ContactPoint;

// Wall seconds of a contact problem's phases, cumulated since the start.
struct ContactPhaseSeconds {
  double pairing = 0;  // updateGeometry
  double solid = 0;    // the solid's assembly within the contact problem's
  double contact = 0;  // the contact terms: evaluation and insertion of the contact points
};

class ContactProblem : public NonlinearSystem, public ContactControls {
 public:
  // `solid` must outlive this. Throws InputError for a zone whose groups are missing.
  ContactProblem(Problem& solid, std::vector<ContactZone> zones);
  ~ContactProblem() override;

  Teuchos::RCP<Vector> createVector() const override;
  void applyDirichlet(double t, Vector& x) const override;
  void completeIncrement(Vector& dx) const override;
  // Over the displacement part of dx (multipliers and slave normals are not lengths).
  double largestDisplacement(const Vector& dx) const override;
  double modelSize() const override { return solid_.modelSize(); }
  double internalForceNorm() const override { return solid_.internalForceNorm(); }
  void assemble(const Vector& x, double t, Vector* residual, bool withTangent) override;
  const Teuchos::RCP<Matrix>& tangent() const override;
  AssemblyFailure assemblyFailure() const override;
  bool takePatternChanged() override;
  // Re-pairs every slave point at x, t. The first call also checks the initial penetration
  // (InputError, on every rank, when a slave point is deeper than its master facet's size).
  bool updateGeometry(const Vector& x, double t) override;
  void commitState(const Vector& x, double t) override;
  // The solid's mass; the inertia acts on the displacement part of x (multipliers have none).
  std::string massUnavailable() const override { return solid_.massUnavailable(); }
  void setInertia(const InertiaTerm& inertia) override;

  // ContactControls: the seam for the algorithms (fixed points, cycling treatments).
  void freezeStatuses(bool frozen) override;
  void freezeThresholds(bool frozen) override;
  std::vector<StatusChange> statusUpdate(const Vector& x, double t) override;
  void applyStatuses(const std::vector<StatusChange>& changes) override;
  double updateThresholds(const Vector& x, double t) override;
  int statusChanges() const override { return statusChanges_; }
  double constraintResidual() const override { return constraintResidual_; }
  // ContactProblemGeometry.cpp.
  std::string passedThrough(const Vector& x) override;
  std::vector<ContactPointState> pointStates() const override;
  void forceStatus(std::size_t point, int status) override;
  bool scaleCoefficients(std::size_t point, double factor) override;
  bool scalingChangesForces(std::size_t point) const override;
  void releaseTreatments() override;
  void releaseForcedStatuses() override;
  void seedInitialStatuses(Vector& x, double t) override;
  void markCycling(std::size_t point, int kind) override;
  void setGeometricTerms(GeometricTerms terms) override;
  bool fullTermsAddToPairing() const override;
  void setFrictionScale(double scale) override;
  bool stepSolidAlone(Vector& x, double t, GO minimumDofs, const SolidSolve& solve) override;

  // Checkpoints (ContactProblemHistory.cpp). The history of the converged state x (call after
  // commitState), the same on every rank (collective).
  ContactHistory convergedHistory(const Vector& x);
  // Puts a checkpoint's history back as commitState(x, t) left it: x's point unknowns (x's
  // displacements must be set already) and every point's history. Throws InputError, the same
  // on every rank, when the checkpoint's points are not this problem's.
  void restoreHistory(const ContactHistory& history, Vector& x, double t);
  // Any vector on x's map (a step's increment): its point unknowns in the order of
  // ContactHistory::unknowns, the same on every rank (collective; the surface state then holds
  // v until the next evaluation imports x again), and back into v's owned entries.
  std::vector<double> pointUnknowns(const Vector& v);
  void setPointUnknowns(const std::vector<double>& unknowns, Vector& v) const;

  // The displacement part of x on the solid's owned map.
  Teuchos::RCP<Vector> displacement(const Vector& x) const;
  const Problem& solid() const { return solid_; }
  const std::vector<ContactZone>& zones() const { return zones_; }
  std::size_t numPoints() const;
  GO numMultipliers() const { return numMultipliers_; }
  // Results of the last assemble() (or commit).
  std::vector<ContactPointResult> results() const;
  // Slave nodes of a zone where, at the last evaluation, the Dirichlet conditions prescribed a
  // friction direction, whose multiplier was dropped (PrescribedSlip.hpp). Collective.
  std::vector<std::int64_t> prescribedSlipNodes(std::size_t zone) const;
  // The slave nodes of a zone whose gap the supports fixed at their last evaluation (held with
  // their master: opened, PrescribedSlip.hpp). Collective.
  std::vector<std::int64_t> prescribedGapNodes(std::size_t zone) const;
  ContactResultants resultants() const;
  // Whether the contact rows keep a symmetric solid tangent symmetric: every zone's law for its
  // friction (ContactLaw::symmetricJacobian), and, with the geometry's terms in the tangent
  // (`geometricTerms`: the geometry in Newton with Geometric Terms pairing or full), no zone
  // whose discretization linearizes its geometry (its terms differentiate the normal along one
  // side only).
  bool tangentSymmetric(bool geometricTerms) const;
  // Whether any point has been closed at a converged step (surfaces that never meet: false).
  bool everInContact() const { return everInContact_; }
  // Adds contact_pressure, tangential_traction, gap, slip, contact_status to a piece made by
  // solid().outputPiece (points in the solid's overlap-node order).
  void addPointData(MeshPiece& piece) const;
  // Wall time spent so far in pairing (updateGeometry), in the solid's assembly and in the
  // contact terms (evaluation and insertion of the contact points) within assemble(): every
  // evaluation counts, a Newton iteration's or not, so no phase is a difference of two timers.
  ContactPhaseSeconds phaseSeconds() const { return seconds_; }

 private:
  // The slave nodes of a zone's points for which `which` held on their owners. Collective.
  std::vector<std::int64_t> pointNodes(std::size_t zone,
                                       const std::function<bool(const ContactPoint&)>& which) const;
  // "node <id> of '<slave group>' (zone <name>)", for messages.
  std::string slaveNodeName(const ContactPoint& pt) const;
  // updateGeometry's work: pairs every point at state x and time t and freezes that geometry.
  bool pairAndFreeze(const Vector& x, double t);
  void layOutPointDofs();
  // Appends to pt.removedDirections the directions the inclined symmetry planes `normals` remove
  // from the node whose dofs start at `first` in pt.dofs.
  void addRemovedDirections(const std::vector<std::array<double, 3>>& normals, std::size_t first,
                            ContactPoint& pt) const;
  // Whether the point carries a normal-field formulation's slave normal among its unknowns.
  bool hasNormalField(const ContactPoint& pt) const;
  // The points' results with the law's pressures; the pressure a user reads (recovered where
  // the law's is not a pressure field, SurfacePressure.hpp).
  std::vector<ContactPointResult> lawResults() const;
  double outputPressure(std::size_t point) const;
  void evaluateAll(const Vector& x, double t);
  void computeLocalStiffness();

  Problem& solid_;
  std::vector<ContactZone> zones_;
  int dim_;
  // The pipeline's stages: per zone its discretization (pairing), the replicated surface state,
  // the point kernel (kinematics and law) and the assembler.
  std::vector<std::unique_ptr<ContactDiscretization>> discretizations_;
  std::vector<ContactPoint> points_;
  std::unique_ptr<ContactSurfaceState> state_;
  std::unique_ptr<ContactPointKernel> kernel_;
  std::unique_ptr<ContactAssembler> assembler_;
  GO numMultipliers_ = 0;
  LO ownedDisplacements_ = 0;
  Teuchos::RCP<const Map> map_;
  std::unordered_set<GO> constrainedSurfaceDofs_;  // Dirichlet dofs of the surface nodes
  // The output pressure and traction per point (ContactPointFields.hpp; NaN: the law's), at
  // each commit.
  RecoveredFields recovered_;
  bool frozenOnce_ = false, everInContact_ = false, layoutChanged_ = false;
  // Why the last geometry update failed on an iterate (empty: it did not): assemble() then
  // returns NaN and assemblyFailure() names it "contact-geometry-failed".
  std::string geometryFailure_;
  ContactPhaseSeconds seconds_;
  int statusChanges_ = 0;
  // The pairing at the last converged state (or the first pairing), for passedThrough.
  std::vector<ContactPoint> convergedPairing_;
  double constraintResidual_ = 0;
  std::vector<double> localStiffness_;  // per point: solid stiffness per area (~E/h), lazily
  bool graphStale_ = false;  // re-paired since the graph was built: rebuild it for a tangent
  GeometricTerms geometricTerms_ = GeometricTerms::none;
};

}  // namespace contactlab
