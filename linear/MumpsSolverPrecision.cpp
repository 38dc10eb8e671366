// MumpsSolver's precision of the factors: large matrices are factorized in single precision
// (SMUMPS) and every solve is refined in double against the matrix itself (IterativeRefinement),
// as is every solve through a low-rank correction (MumpsSolverReuse.cpp).
//
// Measured on this machine's 2 cores (doc/performance.md, "Single-precision factors"): the
// seed-size tube's frictional tangents (133 545 unknowns, LU) factorize in 5.0-5.5 s against
// 8.0-9.2 s in double, in half the memory, and GMRES refinement takes 4 to 9 single solves
// (0.5-1.0 s) to a backward error of 1e-14 to 1e-16 (a double solve without refinement: 5e-13
// to 3e-12); the 125 730-dof tet10 Hertz (LDL^T): 4.5 s against 7.7 s, 3 solves.
#include "base/Elapsed.hpp"
#include "linear/IterativeRefinement.hpp"
#include "linear/MumpsSolverImpl.hpp"

#include <chrono>

namespace contactlab {

namespace {

using Clock = std::chrono::steady_clock;

// A refined solve is accepted at this normwise backward error, the one a correction of double
// factors promised before single factors existed (its measured errors: 1e-20 to 1e-19).
constexpr double kRefinedBackwardError = 1e-13;
// Applications of the approximate inverse per right-hand side: a correction of double factors
// gets two refinements, as it always had (more would only hide a correction gone bad, which a
// factorization answers better); single factors more, since GMRES needs 3 to 9 there.
constexpr int kCorrectionApplications = 3;
constexpr int kSingleFactorApplications = 30;

}  // namespace

bool MumpsSolver::singlePrecisionFactors() const {
  return impl_->factored && impl_->singleFactors;
}

bool MumpsSolver::factorizesInSingle() {
  Impl& m = *impl_;
  if (!m.singleChosen) {
    // Precision automatic, first matrix: the double analysis (needed anyway if double stays)
    // predicts the factorization's flops (RINFOG(1)).
    if (!m.dbl.analysed) analyse(false);
    m.singleChosen = m.dbl.rinfog(1) >= kSingleFactorizationFlops;
  }
  if (*m.singleChosen && !m.sgl) {
    m.sgl = std::make_unique<SingleMumps>();
    m.sgl->initialize(m.comm, static_cast<int>(options_.mode), options_.memoryRelaxation, false);
  }
  return *m.singleChosen;
}

void MumpsSolver::factorize() {
  Impl& m = *impl_;
  if (!factorizesInSingle()) {
    factorizeInDouble();
    return;
  }
  m.factored = false;
  m.singleFactors = false;
  if (!m.sgl->analysed) analyse(true);
  const auto t0 = Clock::now();
  m.singleValues.assign(m.values.begin(), m.values.end());  // rounded to single
  m.sgl->id.a_loc = m.singleValues.data();
  try {
    m.sgl->factorize();
  } catch (const SingularMatrixError&) {
    // A pivot that vanished in single precision: the double factorization decides whether A is
    // singular (it throws then), and a run whose tangents are that close stays in double.
    stats_.factorizationSeconds += secondsSince(t0);
    ++stats_.doublePrecisionFallbacks;
    factorizeInDouble();
    m.singleChosen = false;
    return;
  } catch (...) {
    stats_.factorizationSeconds += secondsSince(t0);
    throw;
  }
  m.singleFactors = true;
  ++stats_.singlePrecisionFactorizations;
  recordFactorization(secondsSince(t0));
  m.currentNormInf = normInf(*m.A);
}

void MumpsSolver::solveWithFactors(const MultiVector& b, MultiVector& x) {
  Impl& m = *impl_;
  MultiVector root(m.rootMap, b.getNumVectors());
  root.doImport(b, *m.toRoot, Tpetra::INSERT);
  solveCentralized(root);
  x.doImport(root, *m.fromRoot, Tpetra::INSERT);
}

void MumpsSolver::solveRefined(const MultiVector& b, MultiVector& x) {
  Impl& m = *impl_;
  const auto t0 = Clock::now();
  const bool correcting = m.correcting;
  RefinementOptions options;
  options.backwardErrorTarget = kRefinedBackwardError;
  options.maxApplications = m.singleFactors ? kSingleFactorApplications : kCorrectionApplications;
  const auto applyInverse = [this, correcting](const MultiVector& in, MultiVector& out) {
    if (correcting)
      solveCorrected(in, out);
    else
      solveWithFactors(in, out);
  };
  const RefinementResult result =
      refineSolution(*m.current, m.currentNormInf, b, x, applyInverse, options);
  stats_.refinementSteps += result.applications - static_cast<int>(b.getNumVectors());
  stats_.solveSeconds += secondsSince(t0);
  if (result.converged) {
    ++stats_.solves;
    return;
  }
  // The approximate inverse is not good enough for A (an ill-conditioned I + G D, or A too
  // ill-conditioned for single-precision factors): factorize A itself; single factors that
  // failed give way to double for the rest of the solver's life (the next tangents are alike).
  if (m.singleFactors && !correcting) {
    m.singleChosen = false;
    ++stats_.doublePrecisionFallbacks;
  }
  factorizeMatrix(m.current);
  solve(b, x);
}

}  // namespace contactlab
