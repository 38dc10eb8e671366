#pragma once
// The first iterate of a step that starts with every contact point open (Newton/Predictor
// 'solid-alone', StaticSolver). There the points' rows do not couple to the displacements, so
// Newton's first iteration is the solid's own move without contact: typically a pressed body
// pushed almost rigidly into its obstacle, whose only use is the statuses it gives, since the
// next iteration's matrix has the contact zone closed. A direct solver factorizes that matrix
// and throws the factors away at once (on a large model a sizeable share of the run:
// doc/algorithms.md "Predictor"). Here the solid's system is solved by CG with a MueLu hierarchy
// to a loose tolerance instead: the statuses need the sign of the gaps, not their digits, and
// Newton corrects the rest from the next iterate on.
#include "formulations/ContactControls.hpp"
#include "linear/LinearSolver.hpp"

#include <memory>

namespace contactlab {

class SolidAlonePredictor {
 public:
  // always: at any size; else (the 'automatic' predictor) from kMinimumDofs displacement dofs,
  // below which a factorization costs less than the hierarchy's setup.
  explicit SolidAlonePredictor(bool always);
  ~SolidAlonePredictor();

  // Moves x's displacements by the solid's step at x, t (ContactControls::stepSolidAlone).
  // Returns false, x unchanged, when the step does not apply or CG did not converge within its
  // iteration budget (a body held only by contact: the direct solver then meets it). Collective.
  bool step(ContactControls& controls, Vector& x, double t);

  static constexpr GO kMinimumDofs = 20000;
  // ||K du + R|| <= kTolerance ||R||.
  static constexpr double kTolerance = 1e-3;
  static constexpr int kMaxIterations = 100;

 private:
  bool always_;
  std::unique_ptr<LinearSolver> solver_;  // built at the first step that needs it
};

}  // namespace contactlab
