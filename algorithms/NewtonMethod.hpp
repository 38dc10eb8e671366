#pragma once
// One Newton solve at a fixed load time, with whatever the algorithm froze (statuses,
// thresholds, geometry) held by the system: the inner loop of the seed's nested algorithms.
// StaticSolver runs the load steps and the fixed points around it; PlainNewton and NoxNewton
// implement it.
#include "core/problem/NonlinearSystem.hpp"
#include "formulations/ContactControls.hpp"

#include <functional>
#include <string>
#include <vector>

namespace contactlab {

struct NewtonRequest {
  double time = 0;
  double target = 0;  // converged when ||R|| <= target (and no status changed)
  // Converged, too, at forcing times the solve's first ||R||: an inexact solve between two
  // fixed-point updates (StaticSolverOptions::fixedPointForcing).
  double forcing = 0;
  int maxIterations = 20;         // linear solves allowed
  bool geometryInNewton = false;  // re-pair at every iterate (the generalized Newton)
  // An update that moves a displacement by more than this is scaled down to it (0: full
  // steps): a failed step's second try (Newton/Max Update times the model's size).
  double maxUpdate = 0;
  // Give up ("diverged") when this many iterates in a row have ||R|| above kStallFactor times
  // the solve's first one, or when the iterates repeat a two-iterate cycle (newtonCycles);
  // 0: never.
  int stallIterations = 0;
  // Converged, too, at the round-off floor of the residual (residualRoundoff) above the target:
  // for a solve a fixed-point update follows, not for one that ends a step (StaticSolver).
  bool roundoffStop = false;
};

// A contact Newton whose iterates stay two orders of magnitude above where the solve started,
// Stall Iterations in a row, does not come back, while converging solves that wander do so
// lower or for fewer iterates: the bound is far on purpose (doc/algorithms.md "Stalled Newton").
inline constexpr double kStallFactor = 100;
// Halvings of an update whose iterate cannot be evaluated (PlainNewton), down to 1/1024 of it.
inline constexpr int kUnevaluableHalvings = 10;

// Whether the last five residual norms of a solve alternate a, b, a, b, a (each equal to the one
// two iterates before to 1e-6 relative; a = b too): Newton on a piecewise law revisiting the
// same two iterates, after the cycling treatment had its chance (it acts on the 4th
// alternation of a point's statuses and changes the residual when it changes anything).
bool newtonCycles(const std::vector<double>& norms);

struct NewtonOutcome {
  int iterations = 0;  // linear solves
  double residual = 0;
  std::string failure;  // empty, or a named reason (StaticSolver's list)
  std::string message;
  double assemblySeconds = 0, linearSolveSeconds = 0;
  int limitedUpdates = 0;       // updates scaled down to NewtonRequest::maxUpdate
  int unevaluableHalvings = 0;  // updates halved because their iterate could not be evaluated
  // Converged at the round-off floor of the residual (residualRoundoff), above the target: 0 or 1.
  int roundoffStops = 0;
  double longestUpdate = 0;  // the largest displacement an update made (before any scaling)
};

class NewtonMethod {
 public:
  // What a method tells its driver at every iterate whose residual and tangent are assembled
  // (iteration 0: the starting point).
  struct Observer {
    // Cycling detection and treatment. It may change the system's frozen state (a status
    // forced, coefficients scaled) and returns true when it did. The residual and tangent at
    // the iterate are then those of the law before the change: the method evaluates them
    // again, so that its step solves the law the next iterate is judged by (a step taken with
    // the untreated law can land the forced points far off equilibrium, doc/algorithms.md
    // "Cycling").
    std::function<bool(int iteration)> treat;
    // The iterate's residual norm as the method goes on with it (after the evaluation a
    // treatment asked for): progress lines, the run's residual, a stop on a signal. Not called
    // for a residual that is not finite.
    std::function<void(int iteration, double residual)> report;
  };
  virtual ~NewtonMethod() = default;
  // x: the start, on return the last iterate. Never throws on a numerical failure.
  virtual NewtonOutcome solve(Vector& x, const NewtonRequest& request,
                              const Observer& observer) = 0;
};

// Whether the contact part of an iterate allows Newton to stop (both drivers): the contact
// statuses unchanged since the previous iterate (a residual that is small only because statuses
// just moved is not a solution yet; iterate 0 has no previous iterate in this solve), and the
// contact equations within `target` as forces (ContactControls::constraintResidual). True
// without contact (controls null).
bool contactSettled(const ContactControls* controls, double target, int iteration);

// Whether Newton may stop at an iterate with residual `norm`: below the target, and
// contactSettled.
bool newtonConverged(double norm, const NewtonRequest& request, const ContactControls* controls,
                     int iteration);

// The failure of a Newton iteration whose linear solve threw SingularMatrixError. The linear
// layer only knows the matrix is singular; what that means for a contact model is worded here:
// the message names the iteration and the solver's detail, StaticSolver appends the step and
// then singularTangentRemedy().
inline constexpr const char* kSingularTangent = "singular-tangent";
std::string singularTangentMessage(int iteration, const std::string& detail);
std::string singularTangentRemedy();

}  // namespace contactlab
