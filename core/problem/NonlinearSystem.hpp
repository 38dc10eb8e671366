#pragma once
// What a load-stepping driver needs from a discrete problem: R(x, t) = 0 with its tangent.
// The solid problem alone implements it (x = displacements); the contact problem adds the
// contact terms and, for the formulations with multipliers, their unknowns to x.
//
// The seam for the algorithms: the geometry of contact (pairing, normals) is frozen between two
// calls of updateGeometry, so Newton sees a residual whose tangent is exact; a driver decides
// when to update it (before each step and after each converged Newton loop: a fixed point).
#include "base/LinearAlgebra.hpp"

#include <Teuchos_RCP.hpp>

#include <string>

namespace contactlab {

// Why the last assemble() could not evaluate its iterate (the residual then holds NaN, so every
// Newton variant stops): a named step failure ("material-update-failed", "inverted-element")
// and a sentence naming the element. Empty code: the last assembly evaluated everything.
struct AssemblyFailure {
  std::string code;
  std::string message;
};

class NonlinearSystem {
 public:
  virtual ~NonlinearSystem() = default;
  virtual Teuchos::RCP<Vector> createVector() const = 0;
  // Sets the prescribed displacements at time t in x (owned entries).
  virtual void applyDirichlet(double t, Vector& x) const = 0;
  // Assembles R(x, t) into `residual` (if not null) and dR/dx into tangent() when requested.
  virtual void assemble(const Vector& x, double t, Vector* residual, bool withTangent) = 0;
  virtual const Teuchos::RCP<Matrix>& tangent() const = 0;
  // Same on every rank (collective inside assemble()).
  virtual AssemblyFailure assemblyFailure() const { return {}; }
  // True when the tangent's sparsity pattern changed since the last call (the linear solver
  // must then redo its symbolic analysis).
  virtual bool takePatternChanged() { return false; }
  // Freezes the geometry at state x and time t. Returns true when it moved enough since the
  // last freeze to change the residual (then Newton has to run again).
  virtual bool updateGeometry(const Vector& /*x*/, double /*t*/) { return false; }
  // The state x at time t is converged: it becomes the reference of the next step.
  virtual void commitState(const Vector& x, double t) = 0;
};

}  // namespace contactlab
