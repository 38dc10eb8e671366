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

#include <stdexcept>
#include <string>

namespace contactlab {

// Why the last assemble() could not evaluate its iterate (the residual then holds NaN, so every
// Newton variant stops): a named step failure ("material-update-failed", "inverted-element")
// and a sentence naming the element. Empty code: the last assembly evaluated everything.
struct AssemblyFailure {
  std::string code;
  std::string message;
};

// The inertia of a regularizing dynamics, c M with M the mass matrix of the materials' densities
// (consistent, or lumped). The algorithm that regularizes owns c and the reference
// (algorithms/SlowDynamics.hpp); the system only knows its mass. With a reference, the residual
// gains the inertia force c M (u - reference) on the displacement part of x; without, only the
// tangent gains c M (the residual stays static). coefficient 0: no inertia.
struct InertiaTerm {
  double coefficient = 0;
  bool lumped = false;
  Teuchos::RCP<const Vector> reference;  // shaped as x; null: the tangent only
};

class NonlinearSystem {
 public:
  virtual ~NonlinearSystem() = default;
  virtual Teuchos::RCP<Vector> createVector() const = 0;
  // Sets the prescribed displacements at time t in x (owned entries).
  virtual void applyDirichlet(double t, Vector& x) const = 0;
  // Completes a Newton increment solved from the tangent: components the system eliminated in
  // terms of others (a symmetry plane's) are written from them. Called after every solve whose
  // result updates x.
  virtual void completeIncrement(Vector& /*dx*/) const {}
  // The largest absolute displacement component of an increment dx (collective): what a Newton
  // update moves the model by. The default takes every entry of dx.
  virtual double largestDisplacement(const Vector& dx) const { return dx.normInf(); }
  // The model's diameter in the reference configuration (Problem: twice the largest distance of
  // a node from the centroid), the length an update is measured against (0: unknown).
  virtual double modelSize() const { return 0; }
  // Assembles R(x, t) into `residual` (if not null) and dR/dx into tangent() when requested.
  virtual void assemble(const Vector& x, double t, Vector* residual, bool withTangent) = 0;
  virtual const Teuchos::RCP<Matrix>& tangent() const = 0;
  // The norm of the internal forces of the last assemble() with a residual, over every dof
  // (constrained ones too): at equilibrium, the loads and the reactions that balance them. What
  // a residual is small against, whatever the increment (0: unknown).
  virtual double internalForceNorm() const { return 0; }
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
  // Why this system cannot carry an inertia term (a sentence naming what lacks a mass), or empty
  // when it can.
  virtual std::string massUnavailable() const { return "this system has no mass matrix"; }
  // Every following assemble() adds the term (until the next call). Only a system whose
  // massUnavailable() is empty accepts a nonzero coefficient.
  virtual void setInertia(const InertiaTerm& inertia) {
    if (inertia.coefficient != 0) throw std::logic_error(massUnavailable());
  }
};

}  // namespace contactlab
