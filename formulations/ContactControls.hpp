#pragma once
// What the algorithms steer in a system with contact, beside R(x, t) = 0: the fixed points on
// the contact statuses and friction thresholds, the per-point state that cycling detection
// watches, and the per-point treatments of cycling. A NonlinearSystem without contact has none
// of this; drivers take a ContactControls pointer that may be null. It lives in formulations,
// not core: it names the algorithms' notions (cycling treatments, the critical-mu scale), which
// the finite-element model below knows nothing of; ContactProblem implements it and the
// algorithms above steer through it.
#include "base/LinearAlgebra.hpp"

#include <Teuchos_RCP.hpp>

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace contactlab {

// The state of one contact point at the last evaluation, as cycling detection sees it.
struct ContactPointState {
  // Zone of the normal law in the (gap, augmented pressure) plane, doc/algorithms.md "Cycling":
  // 0 unpaired; 1 open and apart; 2 open and penetrating; 3 closed and penetrating; 4 closed
  // and apart ("open"/"closed": the sign of the status indicator p^ = p - c g).
  int zone = 0;
  int status = 0;                    // 0 free, 1 stick, 2 slip (ContactStatus)
  double gap = 0;                    // > 0 apart
  double length = 0;                 // the point's size (tributary length), for tolerances
  std::array<double, 3> traction{};  // tangential traction on the slave (direction of friction)
  // Distances to the status switches (the uniqueness diagnostic's ambiguous points): the
  // formulation's contact indicator (closed when >= 0; a pressure-like quantity) and, for a
  // closed point with friction, the relative excess over its friction ball (slip when > 0).
  double contactIndicator = 0;
  double frictionIndicator = 0;
};

// Derivatives of the geometry in the tangent, for a residual whose geometry follows the iterate:
// none (the frozen-geometry tangent), pairing (the master point's motion on its facet, and an
// obstacle's normal), full (also the smoothed normal of a deformable master and its tangents:
// the consistent tangent of the re-paired residual, on the point's piece of the contact law).
enum class GeometricTerms { none, pairing, full };

// A status forced by the cycling treatment: closed, the friction status following the iterate.
constexpr int kForcedClosed = 3;

// A contact point whose status the law gives at an iterate differs from its frozen one.
struct StatusChange {
  std::size_t point = 0;
  int status = 0;        // the law's: 0 open, kForcedClosed closed
  double violation = 0;  // |p^|, the status indicator: how far the frozen status is from holding
  bool forced = false;   // held by a cycling treatment, which the change waits for
};

class ContactControls {
 public:
  virtual ~ContactControls() = default;
  // Fixed points: freeze the contact statuses (open or closed; stick and slip stay with Newton)
  // / the friction thresholds of the last evaluation, or release them.
  virtual void freezeStatuses(bool frozen) = 0;
  virtual void freezeThresholds(bool frozen) = 0;
  // One fixed-point update of the statuses at x, t, in two halves: the contact statuses x gives
  // with them released, where they differ from the frozen ones (nothing changes yet); then the
  // changes the fixed point takes become frozen.
  virtual std::vector<StatusChange> statusUpdate(const Vector& x, double t) = 0;
  virtual void applyStatuses(const std::vector<StatusChange>& changes) = 0;
  // One fixed-point update of the thresholds: those x gives with them released become the
  // frozen ones. Returns the largest change relative to the largest threshold.
  virtual double updateThresholds(const Vector& x, double t) = 0;
  // Points whose status changed between the last two evaluations.
  virtual int statusChanges() const = 0;
  // The norm over the points of ContactPoint::constraintResidual at the last evaluation: how far
  // the multiplier rows' equations are from holding, as forces (Newton converges only when it
  // is within the target too).
  virtual double constraintResidual() const { return 0.0; }

  // At a state x a step would end on: a sentence naming the slave nodes that left their
  // master by passing through it since the last converged state (paired there, unpaired at x
  // and farther behind that pairing's master point than the search reaches), empty if none.
  // Such a state solves the discrete equations (no pairing, no contact force) but not the
  // model. Collective.
  virtual std::string passedThrough(const Vector& /*x*/) { return {}; }

  virtual std::vector<ContactPointState> pointStates() const = 0;
  // Cycling treatments at one point, for the rest of the load step (releaseTreatments ends
  // them): "forced" imposes a status (0 free, 1 stick, 2 slip, kForcedClosed); "automatic"
  // multiplies its coefficients, within bounds tied to the local stiffness (returns false when a
  // bound stops it).
  virtual void forceStatus(std::size_t point, int status) = 0;
  virtual bool scaleCoefficients(std::size_t point, double factor) = 0;
  // Whether scaling a point's coefficients changes its forces within a status (the augmented
  // Lagrangian's p - r_n g and P(Lambda + r_t v)); Lagrange's constants only pick the status.
  virtual bool scalingChangesForces(std::size_t /*point*/) const { return true; }
  virtual void releaseTreatments() = 0;
  // Ends the forced statuses (and their frozen thresholds) only: the state is then judged by
  // the model's own contact law; coefficients and cycling marks stay.
  virtual void releaseForcedStatuses() = 0;
  // The starting point of the first load step (the zones' Initial Contact): sets the contact
  // multipliers of the state x at time t so that the statuses x gives are those asked for.
  virtual void seedInitialStatuses(Vector& x, double t) = 0;
  // Records the cycling kind (CyclingKind as int, 0 none) detected at a point, for the output.
  virtual void markCycling(std::size_t point, int kind) = 0;
  // Multiplies every zone's friction coefficient (1: the model's): the uniqueness diagnostic
  // assembles the Jacobian at two values to split it as A + mu B.
  virtual void setFrictionScale(double scale) = 0;
  // Geometry in Newton: which derivatives of the geometry the tangent includes (GeometricTerms).
  virtual void setGeometricTerms(GeometricTerms terms) = 0;
  // Whether the `full` terms differ from the `pairing` ones in this model (a node-to-segment
  // zone): else a retry with them would solve the same tangent again.
  virtual bool fullTermsAddToPairing() const { return false; }

  // A step of the solid alone (StaticSolver's solid-alone predictor), for a state where no point
  // carries a force yet (every point open, or closed at zero pressure: the touching points of an
  // undeformed state): the solid's own Newton step without contact, K du = -R_u with K and R_u
  // the solid's tangent and residual at x's displacements, which moves a pressed body into its
  // obstacle and so predicts the contact zone. Assembles them, asks `solve` for du (false: no
  // step) and adds du to x's displacements. Returns false, x unchanged, before assembling
  // anything when the solid has fewer than `minimumDofs` displacement dofs, when a point
  // carries a force or when the solid's part is not a system of its own (inclined symmetry
  // planes reduce the whole system); after, when the solid cannot be evaluated at x or when
  // `solve` fails. Collective.
  using SolidSolve = std::function<bool(const Teuchos::RCP<const Matrix>& tangent,
                                        const Vector& rhs, Vector& du, int dofsPerNode)>;
  virtual bool stepSolidAlone(Vector& /*x*/, double /*t*/, GO /*minimumDofs*/,
                              const SolidSolve& /*solve*/) {
    return false;
  }
};

}  // namespace contactlab
