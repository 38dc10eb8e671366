#include "linear/MumpsSolver.hpp"

#include "base/Elapsed.hpp"
#include "linear/BlasThreads.hpp"
#include "linear/MumpsErrors.hpp"
#include "linear/MumpsSolverImpl.hpp"
#include "linear/SolverParameters.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>

#ifdef CONTACTLAB_MUMPS_HAS_SCOTCH
// SCOTCH's random generator (MUMPS' SCOTCH ordering draws from it): reset before each analysis.
extern "C" void SCOTCH_randomReset(void);
#endif

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

namespace contactlab {

namespace {

using Clock = std::chrono::steady_clock;

MPI_Comm rawCommOf(const Comm& comm) {
  if (auto mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm)) return *mpi->getRawMpiComm();
  if (comm.getSize() == 1) return MPI_COMM_SELF;  // Teuchos::SerialComm
  throw LinearSolverError("MUMPS needs a Teuchos::MpiComm communicator");
}

}  // namespace

Teuchos::RCP<const Teuchos::ParameterList> MumpsSolver::validParameters() {
  using Teuchos::tuple;
  auto p = Teuchos::rcp(new Teuchos::ParameterList("mumps"));
  // 'automatic' is the application's to resolve (it knows whether its tangent is symmetric:
  // resolveAutomaticMode in LinearSolverRegistry.hpp); a solver built with it unresolved takes
  // any matrix.
  Teuchos::setStringToIntegralParameter<Mode>(
      "Mode", "automatic", "Matrix type given to MUMPS (SYM)",
      tuple<std::string>("automatic", "general", "symmetric", "symmetric-indefinite"),
      tuple<std::string>("symmetric-indefinite when the model's tangent is symmetric (no "
                         "friction, penalty or augmented Lagrangian, no follower load, no "
                         "node-to-segment geometric terms), general otherwise",
                         "any square matrix: LU factorization (SYM = 0)",
                         "symmetric positive definite: LDL^T without pivoting (SYM = 1); "
                         "reads the lower triangle",
                         "symmetric, possibly indefinite (e.g. saddle point): LDL^T with "
                         "2x2 pivots (SYM = 2); reads the lower triangle"),
      tuple<Mode>(Mode::general, Mode::general, Mode::symmetric, Mode::symmetricIndefinite),
      p.get());
  Teuchos::setStringToIntegralParameter<Ordering>(
      "Ordering", "automatic", "Fill-reducing ordering of the analysis (ICNTL(7))",
      tuple<std::string>("automatic", "scotch", "pord", "amd", "amf", "qamd"),
      tuple<std::string>("SCOTCH from 5 000 unknowns when this build's MUMPS has it "
                         "(Debian's libmumps-ptscotch), else PORD",
                         "SCOTCH nested dissection (an error without libmumps-ptscotch)", "PORD",
                         "approximate minimum degree", "approximate minimum fill",
                         "AMD with quasi-dense row detection"),
      tuple<Ordering>(Ordering::automatic, Ordering::scotch, Ordering::pord, Ordering::amd,
                      Ordering::amf, Ordering::qamd),
      p.get());
  p->set("Memory Relaxation", 20,
         "Percent added to the analysis' workspace estimate (ICNTL(14)); raised automatically "
         "once if the factorization runs out of workspace",
         Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>(0, 10000)));
  Teuchos::setStringToIntegralParameter<int>(
      "Factorization Reuse", "automatic",
      "Whether a matrix may be solved with the factors of the last factorized one",
      tuple<std::string>("automatic", "never"),
      tuple<std::string>(
          "when the matrix equals the last factorized one, or differs from it on at most Max "
          "Correction Rank rows and columns (a Newton iteration where few contact statuses "
          "changed on a solid whose tangent is constant) and MUMPS' flop counts predict it "
          "cheaper, solve through a low-rank (Woodbury) correction of the old factors instead "
          "of factorizing; off when Determinant or Condition Estimate is asked",
          "factorize every matrix"),
      tuple<int>(1, 0), p.get());
  p->set("Max Correction Rank", 3000,
         "Largest number of changed rows and columns a low-rank correction takes (its dense "
         "matrix is that size squared)",
         Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>(0, 20000)));
  Teuchos::setStringToIntegralParameter<Precision>(
      "Precision", "automatic", "Precision of the factors",
      tuple<std::string>("automatic", "double", "single"),
      tuple<std::string>(
          "single when the first matrix's factorization is predicted to cost at least 1e10 "
          "flops (a few tenths of a second: 3D quadratic elements from some 20 000 unknowns; "
          "1.6-1.8 times faster there, in half the memory), double below",
          "double-precision factors, one direct solve per right-hand side",
          "single-precision factors (SMUMPS) for every matrix; each solve is refined in double "
          "against the matrix by GMRES until its normwise backward error is below 1e-13, and a "
          "matrix whose solve does not get there is factorized in double (the solver then stays "
          "in double)"),
      tuple<Precision>(Precision::automatic, Precision::doublePrecision,
                       Precision::singlePrecision),
      p.get());
  p->set("Determinant", false,
         "Compute the determinant at each factorization (ICNTL(33)), as mantissa and exponent");
  p->set("Condition Estimate", false,
         "Run MUMPS' error analysis at each solve (ICNTL(11) = 1) and report the condition "
         "numbers of the system for the first right-hand side; costs more than the solve");
  return p;
}

MumpsSolver::Options MumpsSolver::optionsFrom(const Teuchos::ParameterList& params) {
  const auto valid = validParameters();
  const auto p = validatedParameters(params, *valid, "mumps");
  Options o;
  o.mode = enumParameter<Mode>(p, *valid, "Mode");
  o.ordering = enumParameter<Ordering>(p, *valid, "Ordering");
  if (o.ordering == Ordering::scotch && !hasScotch())
    throw LinearSolverError(
        "mumps/Ordering: 'scotch' needs MUMPS built with SCOTCH (Debian: libmumps-ptscotch-dev, "
        "then reconfigure contactlab); this build has PORD, AMD, AMF and QAMD ('automatic' "
        "picks the best available)");
  o.memoryRelaxation = p.get<int>("Memory Relaxation");
  o.determinant = p.get<bool>("Determinant");
  o.conditionEstimate = p.get<bool>("Condition Estimate");
  o.reuseFactorization = enumParameter<int>(p, *valid, "Factorization Reuse") == 1;
  o.maxCorrectionRank = p.get<int>("Max Correction Rank");
  o.precision = enumParameter<Precision>(p, *valid, "Precision");
  return o;
}

MumpsSolver::MumpsSolver(const Options& options, const Teuchos::RCP<const Comm>& comm)
    : options_(options), impl_(std::make_unique<Impl>()) {
  if (comm.is_null()) throw LinearSolverError("MUMPS needs a communicator (got null)");
#ifdef CONTACTLAB_MUMPS_HAS_SCOTCH
  // SCOTCH 7 orders with one thread per core unless told otherwise, and its threads make the
  // ordering, hence the round-off and a chaotic Newton path, change from run to run (measured:
  // cattaneo-mindlin-2d with full geometric terms, a different residual at iteration 6 in each
  // of 6 runs). One thread (a user's own setting wins): the same matrix, the same ordering. The
  // ordering is a small part of an analysis, and the ranks already use the cores.
  setenv("SCOTCH_PTHREAD_NUMBER", "1", 0);
#endif
  shareCoresAmongRanks(rawCommOf(*comm));
  Impl& m = *impl_;
  m.teuchosComm = comm;
  MPI_Comm_dup(rawCommOf(*comm), &m.comm);
  m.dbl.initialize(m.comm, static_cast<int>(options.mode), options.memoryRelaxation,
                   options.determinant);
  // The determinant and the error analysis describe the factors: double only.
  if (options.determinant || options.conditionEstimate ||
      options.precision == Precision::doublePrecision)
    m.singleChosen = false;
  else if (options.precision == Precision::singlePrecision)
    m.singleChosen = true;
}

MumpsSolver::~MumpsSolver() = default;  // Impl's destructor frees MUMPS (collective)

std::string MumpsSolver::symmetryAssumption() const {
  if (options_.mode == Mode::general) return {};
  return std::string("Mode '") +
         (options_.mode == Mode::symmetric ? "symmetric" : "symmetric-indefinite") +
         "' reads only the lower triangle of a matrix it takes as symmetric (Mode: general "
         "takes any)";
}

void MumpsSolver::takeAnyMatrix() {
  if (options_.mode == Mode::general) return;
  Impl& m = *impl_;
  const int relaxation = m.dbl.icntl(14);
  options_.mode = Mode::general;
  // MUMPS fixes SYM at its initialization: new instances, nothing analysed, nothing to reuse
  // (the triplets held are a lower triangle; the next matrix is passed whole and analysed).
  m.sgl.reset();
  m.singleFactors = false;
  m.dbl.finalize();
  m.dbl.initialize(m.comm, static_cast<int>(Mode::general), relaxation, options_.determinant);
  m.factored = m.correcting = false;
  m.irn.clear();
  m.jcn.clear();
  m.correction.reset();
  m.correctionIndices.clear();
}

void MumpsSolver::setMatrix(const Teuchos::RCP<const Matrix>& A, bool /*patternChanged*/) {
  Impl& m = *impl_;
  if (A.is_null()) throw LinearSolverError("MUMPS was given a null matrix");
  if (!A->isFillComplete())
    throw LinearSolverError("MUMPS needs a fill-completed matrix (call fillComplete first)");
  int compare = MPI_UNEQUAL;
  MPI_Comm_compare(rawCommOf(*A->getComm()), m.comm, &compare);
  if (compare != MPI_CONGRUENT && compare != MPI_IDENT)
    throw LinearSolverError("the matrix given to MUMPS lives on another communicator");
  const auto N = A->getGlobalNumRows();
  if (N != A->getGlobalNumCols())
    throw LinearSolverError("MUMPS needs a square matrix (got " + std::to_string(N) + " x " +
                            std::to_string(A->getGlobalNumCols()) + ")");
  if (N > static_cast<Tpetra::global_size_t>(std::numeric_limits<MUMPS_INT>::max()))
    throw LinearSolverError("matrix order " + std::to_string(N) +
                            " exceeds MUMPS' 32-bit index range");
  if (reusesFactorization() && m.factored && correctFrom(A)) return;
  factorizeMatrix(A);
}

void MumpsSolver::factorizeMatrix(const Teuchos::RCP<const Matrix>& A) {
  Impl& m = *impl_;
  m.correcting = false;
  m.current = A;
  const auto N = A->getGlobalNumRows();

  // Triplets of the local rows, 1-based global indices; lower triangle in symmetric modes.
  const auto rowMap = A->getRowMap();
  const auto colMap = A->getColMap();
  const auto local = A->getLocalMatrixHost();
  const bool lowerOnly = options_.mode != Mode::general;
  std::vector<MUMPS_INT> irn, jcn;
  std::vector<double> values;
  irn.reserve(local.nnz());
  jcn.reserve(local.nnz());
  values.reserve(local.nnz());
  for (LO r = 0; r < static_cast<LO>(local.numRows()); ++r) {
    const GO row = rowMap->getGlobalElement(r);
    for (auto k = local.graph.row_map(r); k < local.graph.row_map(r + 1); ++k) {
      const GO col = colMap->getGlobalElement(local.graph.entries(k));
      if (lowerOnly && col > row) continue;
      irn.push_back(static_cast<MUMPS_INT>(row + 1));
      jcn.push_back(static_cast<MUMPS_INT>(col + 1));
      values.push_back(local.values(k));
    }
  }

  // A new analysis when the pattern differs from the analysed one on any rank. The caller's
  // patternChanged is not needed: the triplets are compared, and the analysis of a distributed
  // matrix (ICNTL(18) = 3) reads its pattern only, so an equal pattern keeps its analysis and
  // its factors come out bitwise the same. A study's next run on the same mesh builds a new
  // matrix of the pattern analysed for the last one (the 2D Hertz study: 10 ms a run, 12 % of
  // its in-process time, doc/performance.md "Studies in one process").
  const bool held = m.dbl.analysed || (m.sgl && m.sgl->analysed);
  int changed = (!held || irn != m.irn || jcn != m.jcn) ? 1 : 0;
  int anyChanged = 0;
  Teuchos::reduceAll(*m.teuchosComm, Teuchos::REDUCE_MAX, changed, Teuchos::outArg(anyChanged));
  m.A = A;
  m.values = std::move(values);
  if (anyChanged) {
    // Until an analysis succeeds: a failed check below forces a new one.
    m.dbl.analysed = m.dbl.factored = false;
    if (m.sgl) m.sgl->analysed = m.sgl->factored = false;
    m.factored = false;
    // Global ids index MUMPS' unknowns: they must be 0-based, in [0, N), each row on one rank.
    const GO minId = std::min(rowMap->getMinAllGlobalIndex(), colMap->getMinAllGlobalIndex());
    const GO maxId = std::max(rowMap->getMaxAllGlobalIndex(), colMap->getMaxAllGlobalIndex());
    if (minId < 0 || maxId >= static_cast<GO>(N))
      throw LinearSolverError("MUMPS needs global ids in [0, " + std::to_string(N) +
                              "); the matrix uses [" + std::to_string(minId) + ", " +
                              std::to_string(maxId) + "]");
    if (!rowMap->isOneToOne())
      throw LinearSolverError("MUMPS needs a row map where each row is owned by one rank");
    m.irn = std::move(irn);
    m.jcn = std::move(jcn);
    // PORD aborts the process on some tiny graphs ("orderMinPriority: no valid number of stages
    // in multisector", a one-element model); any ordering is as good as another there.
    constexpr std::int64_t kPordMinimumSize = 64;
    // SCOTCH's nested dissection predicts 14-20 % fewer factorization flops than PORD from
    // ~8 000 unknowns on (cattaneo-mindlin-2d, hertz-3d-two-body, hertz-3d on tet10 at 46 572
    // dofs) and 13-35 % more on the 2 000-4 000 of hertz-2d and block-compression-3d, where a
    // factorization costs milliseconds either way (doc/performance.md).
    constexpr std::int64_t kScotchMinimumSize = 5000;
    Ordering ordering = options_.ordering;
    if (ordering == Ordering::automatic)
      ordering = hasScotch() && static_cast<std::int64_t>(N) >= kScotchMinimumSize
                     ? Ordering::scotch
                     : Ordering::pord;
    if (ordering == Ordering::pord && static_cast<std::int64_t>(N) < kPordMinimumSize)
      ordering = Ordering::amd;
    m.ordering = static_cast<MUMPS_INT>(ordering);
    // The map that gathers every global index on rank 0, in order: MUMPS' centralized vectors.
    m.rootMap = Teuchos::rcp(new Map(N, m.isRoot() ? N : 0, 0, A->getComm()));
    m.rangeMap = Teuchos::null;
    m.domainMap = Teuchos::null;
  }
  factorize();
  keepReference(*A);
}

void MumpsSolver::analyse(bool singlePrecision) {
  Impl& m = *impl_;
  const auto t0 = Clock::now();
  const auto analyseOn = [&](auto& mumps, MUMPS_INT ordering, MUMPS_INT* pivotOrder) {
    mumps.analysed = mumps.factored = false;
    mumps.id.n = static_cast<MUMPS_INT>(m.A->getGlobalNumRows());
    mumps.id.nnz_loc = static_cast<MUMPS_INT8>(m.irn.size());
    mumps.id.irn_loc = m.irn.data();
    mumps.id.jcn_loc = m.jcn.data();
    mumps.icntl(7) = ordering;
    mumps.id.perm_in = pivotOrder;
#ifdef CONTACTLAB_MUMPS_HAS_SCOTCH
    // SCOTCH's generator state carries over from one analysis to the next in a process, so a
    // matrix's ordering (hence its round-off) would depend on how many analyses came before it
    // (measured: the Cattaneo run below takes another path without the reset). Reset to the
    // fixed seed, every analysis orders a given matrix the same way.
    SCOTCH_randomReset();
#endif
    mumps.run(1);
    mumps.check("analysis");
    mumps.analysed = true;
  };
  if (singlePrecision && m.dbl.analysed) {
    // Precision automatic analyses the pattern in double first (its flop count decides): the
    // single analysis takes that pivot order (ICNTL(7) = 1) instead of ordering the same
    // pattern again. The peers' 125 730-dof Hertz: 3.1 -> 1.9 s of analysis (SCOTCH's 1.2 s
    // once, not twice; doc/performance.md, "Single-precision factors").
    // MUMPS reads PERM_IN during this analysis only.
    std::vector<MUMPS_INT> pivotOrder;
    if (m.isRoot()) pivotOrder.assign(m.dbl.id.sym_perm, m.dbl.id.sym_perm + m.dbl.id.n);
    analyseOn(*m.sgl, 1, m.isRoot() ? pivotOrder.data() : nullptr);
  } else if (singlePrecision) {
    analyseOn(*m.sgl, m.ordering, nullptr);
  } else {
    analyseOn(m.dbl, m.ordering, nullptr);
  }
  ++stats_.analyses;
  stats_.analysisSeconds += secondsSince(t0);
}

void MumpsSolver::factorizeInDouble() {
  Impl& m = *impl_;
  m.factored = false;
  m.singleFactors = false;
  if (!m.dbl.analysed) analyse(false);
  const auto t0 = Clock::now();
  m.dbl.id.a_loc = m.values.data();
  try {
    m.dbl.factorize();
  } catch (...) {
    stats_.factorizationSeconds += secondsSince(t0);
    throw;
  }
  recordFactorization(secondsSince(t0));
}

void MumpsSolver::recordFactorization(double seconds) {
  Impl& m = *impl_;
  m.factored = true;
  m.withFactors([&m](const auto& mumps) {
    m.referenceFlops = mumps.rinfog(3);
    m.referenceEntries = mumps.factorEntries();
  });
  ++stats_.factorizations;
  stats_.factorizationSeconds += seconds;
  if (m.rangeMap != m.A->getRangeMap() || m.domainMap != m.A->getDomainMap()) {
    m.rangeMap = m.A->getRangeMap();
    m.domainMap = m.A->getDomainMap();
    m.toRoot = Teuchos::rcp(new Import(m.rangeMap, m.rootMap));
    m.fromRoot = Teuchos::rcp(new Import(m.rootMap, m.domainMap));
  }
}

void MumpsSolver::solve(const MultiVector& b, MultiVector& x) {
  Impl& m = *impl_;
  if (!m.factored) throw LinearSolverError("MUMPS solve called before a successful setMatrix");
  const size_t nrhs = b.getNumVectors();
  if (x.getNumVectors() != nrhs)
    throw LinearSolverError("MUMPS solve: b has " + std::to_string(nrhs) + " columns, x has " +
                            std::to_string(x.getNumVectors()));
  if (!b.getMap()->isSameAs(*m.rangeMap) || !x.getMap()->isSameAs(*m.domainMap))
    throw LinearSolverError("MUMPS solve: b and x must live on the matrix's range / domain map");
  if (nrhs == 0) return;
  if (m.correcting || m.singleFactors) {
    solveRefined(b, x);
    return;
  }
  const auto t0 = Clock::now();

  MultiVector root(m.rootMap, nrhs);
  root.doImport(b, *m.toRoot, Tpetra::INSERT);
  {
    Teuchos::ArrayRCP<double> data;
    if (m.isRoot()) {
      data = root.get1dViewNonConst();
      m.dbl.id.rhs = data.getRawPtr();
      m.dbl.id.lrhs = static_cast<MUMPS_INT>(std::max<size_t>(root.getStride(), 1));
    }
    // The error analysis works on one right-hand side: the first one gets it, alone.
    size_t first = 0;
    if (options_.conditionEstimate) {
      m.dbl.id.nrhs = 1;
      m.dbl.icntl(11) = 1;
      m.dbl.run(3);
      m.dbl.icntl(11) = 0;
      m.dbl.check("solve");
      m.lastErrorAnalysis = ErrorAnalysis{m.dbl.rinfog(7), m.dbl.rinfog(8), m.dbl.rinfog(9),
                                          m.dbl.rinfog(10), m.dbl.rinfog(11)};
      first = 1;
    }
    if (first < nrhs) {
      if (m.isRoot()) m.dbl.id.rhs = data.getRawPtr() + first * m.dbl.id.lrhs;
      m.dbl.id.nrhs = static_cast<MUMPS_INT>(nrhs - first);
      m.dbl.run(3);
      m.dbl.check("solve");
    }
    m.dbl.id.rhs = nullptr;
  }
  x.doImport(root, *m.fromRoot, Tpetra::INSERT);
  ++stats_.solves;
  stats_.solveSeconds += secondsSince(t0);
}

std::optional<Determinant> MumpsSolver::determinant() const {
  // Determinant asked: the factors are double (the constructor chose so).
  if (!options_.determinant || !impl_->factored) return std::nullopt;
  // RINFOG(12) * 2^INFOG(34); RINFOG(13) is the imaginary part (complex arithmetic only).
  return Determinant::normalized(impl_->dbl.rinfog(12), impl_->dbl.infog(34));
}

std::optional<double> MumpsSolver::conditionEstimate() const {
  if (!impl_->lastErrorAnalysis) return std::nullopt;
  return std::max(impl_->lastErrorAnalysis->cond1, impl_->lastErrorAnalysis->cond2);
}

std::optional<MumpsSolver::ErrorAnalysis> MumpsSolver::errorAnalysis() const {
  return impl_->lastErrorAnalysis;
}

std::optional<long> MumpsSolver::negativePivots() const {
  if (options_.mode == Mode::general || !impl_->factored) return std::nullopt;
  return impl_->withFactors([](const auto& mumps) -> long { return mumps.infog(12); });
}

int MumpsSolver::memoryRelaxation() const {
  return impl_->withFactors([](const auto& mumps) { return mumps.icntl(14); });
}

bool MumpsSolver::hasScotch() {
#ifdef CONTACTLAB_MUMPS_HAS_SCOTCH
  return true;
#else
  return false;
#endif
}

std::optional<MumpsSolver::Ordering> MumpsSolver::orderingUsed() const {
  const Impl& m = *impl_;
  if (m.singleFactors ? !m.sgl->analysed : !m.dbl.analysed) return std::nullopt;
  // Single factors analysed with the double analysis' pivot order (INFOG(7) = 1): its ordering.
  if (m.singleFactors && m.sgl->infog(7) == 1 && m.dbl.analysed)
    return static_cast<Ordering>(m.dbl.infog(7));
  return m.withFactors([](const auto& mumps) { return static_cast<Ordering>(mumps.infog(7)); });
}

}  // namespace contactlab
