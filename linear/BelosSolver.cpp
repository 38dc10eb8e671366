#include "linear/BelosSolver.hpp"

#include "base/Elapsed.hpp"
#include "linear/SolverParameters.hpp"

#include <BelosLinearProblem.hpp>
#include <BelosSolverFactory_Tpetra.hpp>
#include <BelosTpetraAdapter.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>

#include <algorithm>
#include <chrono>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

namespace contactlab {

namespace {

using Clock = std::chrono::steady_clock;

using Kind = PreconditionerOptions::Kind;

const char* nameOf(BelosSolver::Method method) {
  return method == BelosSolver::Method::cg ? "cg" : "gmres";
}

const char* nameOf(Kind kind) {
  switch (kind) {
    case Kind::none:
      return "none";
    case Kind::ifpack2Sgs:
      return "ifpack2-sgs";
    case Kind::ifpack2Riluk:
      return "ifpack2-riluk";
    case Kind::ifpack2Ilut:
      return "ifpack2-ilut";
    case Kind::muelu:
      return "muelu";
  }
  return "?";
}

// The sentence of a Teuchos/Belos exception, without the header TEUCHOS_TEST_FOR_EXCEPTION
// puts first ("./packages/belos/src/BelosX.hpp:574:", "Throw number = 1", "Throw test that
// evaluated to true: <code>"): a user gets the reason, not an installed header's path.
std::string firstLine(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    line = line.substr(first);
    const bool location = line.back() == ':' && (line.find(".hpp:") != std::string::npos ||
                                                 line.find(".cpp:") != std::string::npos ||
                                                 line.find(".h:") != std::string::npos);
    if (location || line.rfind("Throw number", 0) == 0 || line.rfind("Throw test that", 0) == 0)
      continue;
    return line;
  }
  return "an internal error of Belos";
}

// A solve whose true residual exceeds this multiple of the tolerance throws even when Belos
// reports convergence (its implicit residual can drift from the true one).
constexpr double kDriftFactor = 10.0;

}  // namespace

struct BelosSolver::Impl {
  using Problem = Belos::LinearProblem<Scalar, MultiVector, Operator>;
  using Manager = Belos::SolverManager<Scalar, MultiVector, Operator>;
  Teuchos::RCP<const Comm> comm;
  Teuchos::RCP<const Matrix> A;
  Teuchos::RCP<Operator> preconditioner;
  Teuchos::RCP<const MultiVector> nullSpace;
  Teuchos::RCP<Manager> manager;
};

Teuchos::RCP<const Teuchos::ParameterList> BelosSolver::validParameters() {
  using Teuchos::rcp;
  using Teuchos::tuple;
  using IntRange = Teuchos::EnhancedNumberValidator<int>;
  using RealRange = Teuchos::EnhancedNumberValidator<double>;
  auto p = rcp(new Teuchos::ParameterList("belos"));
  Teuchos::setStringToIntegralParameter<Method>(
      "Method", "cg", "Krylov method", tuple<std::string>("cg", "gmres"),
      tuple<std::string>("conjugate gradients: symmetric positive definite A and preconditioner",
                         "restarted GMRES, right-preconditioned: any nonsingular A"),
      tuple<Method>(Method::cg, Method::gmres), p.get());
  Teuchos::setStringToIntegralParameter<Kind>(
      "Preconditioner", "ifpack2-sgs", "Preconditioner, rebuilt at each new matrix",
      tuple<std::string>("none", "ifpack2-sgs", "ifpack2-riluk", "ifpack2-ilut", "muelu"),
      tuple<std::string>("no preconditioner", "Ifpack2 symmetric Gauss-Seidel (Sweeps, Damping)",
                         "Ifpack2 additive Schwarz with ILU(k) subdomains (Fill Level, Overlap)",
                         "Ifpack2 additive Schwarz with ILUT subdomains (Fill Ratio, Drop "
                         "Tolerance, Overlap); gmres only: ILUT is not symmetric",
                         "MueLu smoothed aggregation AMG with Gauss-Seidel smoothing and a "
                         "relaxed coarse level; uses the near-null space when one is given"),
      tuple<Kind>(Kind::none, Kind::ifpack2Sgs, Kind::ifpack2Riluk, Kind::ifpack2Ilut, Kind::muelu),
      p.get());
  p->set("Tolerance", 1e-10, "Convergence when ||b - A x|| <= Tolerance * ||b||",
         rcp(new RealRange(0.0, 1.0)));
  p->set("Max Iterations", 1000, "Iterations allowed before the solve fails",
         rcp(new IntRange(1, 100000000)));
  p->set("Restart", 100, "GMRES: Krylov vectors kept before a restart",
         rcp(new IntRange(1, 100000)));
  Teuchos::setStringToIntegralParameter<Verbosity>(
      "Verbosity", "none", "What Belos prints (rank 0, standard output)",
      tuple<std::string>("none", "summary", "iterations"),
      tuple<std::string>("errors only", "a summary per solve", "the residual at each iteration"),
      tuple<Verbosity>(Verbosity::none, Verbosity::summary, Verbosity::iterations), p.get());
  const PreconditionerOptions d;
  p->set("Sweeps", d.sweeps, "Gauss-Seidel sweeps per application (ifpack2-sgs, muelu smoother)",
         rcp(new IntRange(1, 1000)));
  p->set("Damping", d.damping, "Gauss-Seidel damping factor (ifpack2-sgs, muelu smoother)",
         rcp(new RealRange(0.0, 2.0)));
  p->set("Fill Level", d.fillLevel, "ILU(k) level of fill k (ifpack2-riluk)",
         rcp(new IntRange(0, 100)));
  p->set("Fill Ratio", d.fillRatio,
         "ILUT: entries kept per row, relative to the row of A, >= 1 (ifpack2-ilut)",
         rcp(new RealRange(1.0, 1000.0)));
  p->set("Drop Tolerance", d.dropTolerance,
         "ILUT: entries smaller than this (relative to the row) are dropped (ifpack2-ilut)",
         rcp(new RealRange(0.0, 1.0)));
  p->set("Overlap", d.overlap,
         "Additive Schwarz overlap in layers of rows (ifpack2-riluk, ifpack2-ilut)",
         rcp(new IntRange(0, 100)));
  p->set("Block Size", d.blockSize,
         "MueLu: unknowns per mesh node, kept together in aggregates (2 or 3 in elasticity)",
         rcp(new IntRange(1, 100)));
  p->set("Max Levels", d.maxLevels, "MueLu: maximum number of levels", rcp(new IntRange(1, 100)));
  p->set("Coarse Max Size", d.coarseMaxSize,
         "MueLu: coarsening stops below this number of unknowns", rcp(new IntRange(1, 10000000)));
  p->set("Coarse Sweeps", d.coarseSweeps,
         "MueLu: Gauss-Seidel sweeps on the coarsest level (no direct coarse solve: KLU2 is "
         "wrong on more than one rank)",
         rcp(new IntRange(1, 1000)));
  return p;
}

BelosSolver::Options BelosSolver::optionsFrom(const Teuchos::ParameterList& params) {
  const auto valid = validParameters();
  const auto p = validatedParameters(params, *valid, "belos");
  Options o;
  o.method = enumParameter<Method>(p, *valid, "Method");
  o.tolerance = p.get<double>("Tolerance");
  o.maxIterations = p.get<int>("Max Iterations");
  o.restart = p.get<int>("Restart");
  o.verbosity = enumParameter<Verbosity>(p, *valid, "Verbosity");
  auto& q = o.preconditioner;
  q.kind = enumParameter<Kind>(p, *valid, "Preconditioner");
  q.sweeps = p.get<int>("Sweeps");
  q.damping = p.get<double>("Damping");
  q.fillLevel = p.get<int>("Fill Level");
  q.fillRatio = p.get<double>("Fill Ratio");
  q.dropTolerance = p.get<double>("Drop Tolerance");
  q.overlap = p.get<int>("Overlap");
  q.blockSize = p.get<int>("Block Size");
  q.maxLevels = p.get<int>("Max Levels");
  q.coarseMaxSize = p.get<int>("Coarse Max Size");
  q.coarseSweeps = p.get<int>("Coarse Sweeps");
  return o;
}

BelosSolver::BelosSolver(const Options& options, const Teuchos::RCP<const Comm>& comm)
    : options_(options), impl_(std::make_unique<Impl>()) {
  if (comm.is_null()) throw LinearSolverError("Belos needs a communicator (got null)");
  if (options.method == Method::cg && options.preconditioner.kind == Kind::ifpack2Ilut)
    throw LinearSolverError(
        "Belos cg cannot use ifpack2-ilut: ILUT drops entries differently in L and U, so the "
        "preconditioner is not symmetric and CG stagnates; use gmres, or ifpack2-riluk, "
        "ifpack2-sgs or muelu with cg");
  impl_->comm = comm;
  auto params = Teuchos::rcp(new Teuchos::ParameterList);
  params->set("Convergence Tolerance", options.tolerance);
  params->set("Maximum Iterations", options.maxIterations);
  int verbosity = Belos::Errors + Belos::Warnings;
  if (options.verbosity != Verbosity::none) verbosity += Belos::FinalSummary;
  if (options.verbosity == Verbosity::iterations)
    verbosity += Belos::IterationDetails + Belos::StatusTestDetails;
  params->set("Verbosity", verbosity);
  params->set("Output Style", static_cast<int>(Belos::Brief));
  params->set("Output Frequency", options.verbosity == Verbosity::iterations ? 1 : -1);
  params->set("Implicit Residual Scaling", "Norm of RHS");
  if (options.method == Method::gmres) {
    params->set("Num Blocks", options.restart);
    params->set("Maximum Restarts", options.maxIterations / options.restart + 1);
    params->set("Explicit Residual Scaling", "Norm of RHS");
  }
  Belos::SolverFactory<Scalar, MultiVector, Operator> factory;
  impl_->manager = factory.create(options.method == Method::cg ? "CG" : "GMRES", params);
}

BelosSolver::~BelosSolver() = default;

std::string BelosSolver::symmetryAssumption() const {
  if (options_.method != Method::cg) return {};
  return "Method 'cg' (the default) needs a symmetric positive definite matrix (Method: gmres "
         "takes any)";
}

void BelosSolver::setNearNullSpace(const Teuchos::RCP<const MultiVector>& nullSpace) {
  impl_->nullSpace = nullSpace;
}

void BelosSolver::setMatrix(const Teuchos::RCP<const Matrix>& A, bool /*patternChanged*/) {
  Impl& m = *impl_;
  if (A.is_null()) throw LinearSolverError("Belos was given a null matrix");
  if (!A->isFillComplete())
    throw LinearSolverError("Belos needs a fill-completed matrix (call fillComplete first)");
  m.A = A;
  m.preconditioner = Teuchos::null;
  auto prec = options_.preconditioner;
  prec.symmetric = options_.method == Method::cg;
  const auto t0 = Clock::now();
  try {
    if (prec.kind == Kind::muelu)
      m.preconditioner = createMueLuPreconditioner(A, m.nullSpace, prec);
    else if (prec.kind != Kind::none)
      m.preconditioner = createIfpack2Preconditioner(A, prec);
  } catch (const std::exception& e) {
    throw LinearSolverError(std::string("Belos preconditioner ") + nameOf(prec.kind) +
                            " setup failed: " + firstLine(e.what()));
  }
  ++stats_.factorizations;
  stats_.factorizationSeconds += secondsSince(t0);
}

void BelosSolver::solve(const MultiVector& b, MultiVector& x) {
  Impl& m = *impl_;
  if (m.A.is_null()) throw LinearSolverError("Belos solve called before setMatrix");
  const size_t nrhs = b.getNumVectors();
  if (x.getNumVectors() != nrhs)
    throw LinearSolverError("Belos solve: b and x have different numbers of columns");
  const auto t0 = Clock::now();
  x.putScalar(0.0);
  std::vector<double> bNorm(nrhs), rNorm(nrhs);
  b.norm2(bNorm);
  if (*std::max_element(bNorm.begin(), bNorm.end()) > 0) {
    auto problem =
        Teuchos::rcp(new Impl::Problem(m.A, Teuchos::rcpFromRef(x), Teuchos::rcpFromRef(b)));
    if (!m.preconditioner.is_null()) {
      if (options_.method == Method::cg)
        problem->setLeftPrec(m.preconditioner);
      else
        problem->setRightPrec(m.preconditioner);
    }
    problem->setProblem();
    Belos::ReturnType result = Belos::Unconverged;
    try {
      m.manager->setProblem(problem);
      result = m.manager->solve();
    } catch (const std::exception& e) {
      throw LinearSolverError(std::string("Belos ") + nameOf(options_.method) +
                              " failed (is the matrix or preconditioner not symmetric positive "
                              "definite?): " +
                              firstLine(e.what()));
    }
    const int iterations = m.manager->getNumIters();
    stats_.iterations = iterations;
    MultiVector r(b, Teuchos::Copy);
    m.A->apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
    r.norm2(rNorm);
    double worst = 0;
    for (size_t j = 0; j < nrhs; ++j)
      worst = std::max(worst, bNorm[j] > 0 ? rNorm[j] / bNorm[j] : rNorm[j]);
    stats_.relativeResidual = worst;
    if (result != Belos::Converged || !(worst <= kDriftFactor * options_.tolerance))
      throw LinearSolverError(std::string("Belos ") + nameOf(options_.method) +
                              " with preconditioner " + nameOf(options_.preconditioner.kind) +
                              " did not converge: relative residual " + formatNumber(worst) +
                              " after " + std::to_string(iterations) + " iterations (Tolerance " +
                              formatNumber(options_.tolerance) + ", Max Iterations " +
                              std::to_string(options_.maxIterations) + ")");
  } else {
    stats_.relativeResidual = 0;  // x = 0 is exact
    stats_.iterations = 0;
  }
  ++stats_.solves;
  stats_.solveSeconds += secondsSince(t0);
}

}  // namespace contactlab
