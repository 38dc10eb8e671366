#include "linear/Klu2Solver.hpp"

#include "base/Elapsed.hpp"
#include "linear/SolverParameters.hpp"

#include <Amesos2.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>

#include <algorithm>
#include <chrono>
#include <exception>
#include <numeric>
#include <vector>

namespace contactlab {

namespace {

using Clock = std::chrono::steady_clock;

// Runs `work` on rank 0 only. An exception there is rethrown on every rank, so that all ranks
// leave the collective call together: prefix + what() for LinearSolverError, prefix + `meaning`
// for anything else (Amesos2's own messages are pages of file names and line numbers).
template <class Work>
void onRoot(const Comm& comm, const std::string& prefix, const std::string& meaning, Work&& work) {
  std::string error;
  if (comm.getRank() == 0) {
    try {
      work();
    } catch (const LinearSolverError& e) {
      error = e.what();
    } catch (const std::exception&) {
      error = meaning;
    }
  }
  int length = static_cast<int>(error.size());
  Teuchos::broadcast(comm, 0, &length);
  if (length == 0) return;
  error.resize(length);
  Teuchos::broadcast(comm, 0, length, &error[0]);
  throw LinearSolverError(prefix + error);
}

}  // namespace

struct Klu2Solver::Impl {
  using Amesos2Solver = Amesos2::Solver<Matrix, MultiVector>;
  Teuchos::RCP<const Comm> comm;
  Teuchos::RCP<const Comm> rootComm;  // rank 0 alone; null on the other ranks
  Teuchos::RCP<const Matrix> A;
  Teuchos::RCP<const Map> rowMap, rootMap;  // rootMap: every global index on rank 0, in order
  Teuchos::RCP<const Import> rowsToRoot;    // rows of A to rank 0
  Teuchos::RCP<const Map> rangeMap, domainMap;
  Teuchos::RCP<const Import> toRoot, fromRoot;  // vectors: range map -> root -> domain map
  // Rank 0 only: the gathered matrix on rootComm and its factorization.
  Teuchos::RCP<const Map> serialMap;
  Teuchos::RCP<Matrix> serialA;
  std::vector<size_t> rowPtr;
  std::vector<LO> colInd;
  Teuchos::RCP<Amesos2Solver> solver;
  bool factored = false;

  bool isRoot() const { return comm->getRank() == 0; }
};

Teuchos::RCP<const Teuchos::ParameterList> Klu2Solver::validParameters() {
  auto p = Teuchos::rcp(new Teuchos::ParameterList("klu2"));
  p->set("Residual Tolerance", 1e-8,
         "Each solve checks max_j ||b_j - A x_j|| / ||b_j|| and throws above this value, so a "
         "wrong answer is never returned silently",
         Teuchos::rcp(new Teuchos::EnhancedNumberValidator<double>(0.0, 1.0)));
  return p;
}

Klu2Solver::Options Klu2Solver::optionsFrom(const Teuchos::ParameterList& params) {
  const auto p = validatedParameters(params, *validParameters(), "klu2");
  Options o;
  o.residualTolerance = p.get<double>("Residual Tolerance");
  return o;
}

Klu2Solver::Klu2Solver(const Options& options, const Teuchos::RCP<const Comm>& comm)
    : options_(options), impl_(std::make_unique<Impl>()) {
  if (comm.is_null()) throw LinearSolverError("KLU2 needs a communicator (got null)");
  impl_->comm = comm;
  const int root[] = {0};
  impl_->rootComm = comm->createSubcommunicator(Teuchos::ArrayView<const int>(root, 1));
}

Klu2Solver::~Klu2Solver() = default;

void Klu2Solver::setMatrix(const Teuchos::RCP<const Matrix>& A, bool patternChanged) {
  Impl& m = *impl_;
  if (A.is_null()) throw LinearSolverError("KLU2 was given a null matrix");
  if (!A->isFillComplete())
    throw LinearSolverError("KLU2 needs a fill-completed matrix (call fillComplete first)");
  const auto N = A->getGlobalNumRows();
  if (N != A->getGlobalNumCols()) throw LinearSolverError("KLU2 needs a square matrix");

  // The importer of rows to rank 0 depends on the row map only.
  if (m.rowMap.is_null() || !m.rowMap->isSameAs(*A->getRowMap())) {
    const auto rowMap = A->getRowMap();
    const auto colMap = A->getColMap();
    const GO minId = std::min(rowMap->getMinAllGlobalIndex(), colMap->getMinAllGlobalIndex());
    const GO maxId = std::max(rowMap->getMaxAllGlobalIndex(), colMap->getMaxAllGlobalIndex());
    if (minId < 0 || maxId >= static_cast<GO>(N))
      throw LinearSolverError("KLU2 needs global ids in [0, " + std::to_string(N) +
                              "); the matrix uses [" + std::to_string(minId) + ", " +
                              std::to_string(maxId) + "]");
    if (!rowMap->isOneToOne())
      throw LinearSolverError("KLU2 needs a row map where each row is owned by one rank");
    m.rowMap = rowMap;
    m.rootMap = Teuchos::rcp(new Map(N, m.isRoot() ? N : 0, 0, A->getComm()));
    m.rowsToRoot = Teuchos::rcp(new Import(rowMap, m.rootMap));
    if (m.isRoot()) m.serialMap = Teuchos::rcp(new Map(N, 0, m.rootComm));
    m.rangeMap = Teuchos::null;
  }
  if (m.rangeMap != A->getRangeMap() || m.domainMap != A->getDomainMap()) {
    m.rangeMap = A->getRangeMap();
    m.domainMap = A->getDomainMap();
    m.toRoot = Teuchos::rcp(new Import(m.rangeMap, m.rootMap));
    m.fromRoot = Teuchos::rcp(new Import(m.rootMap, m.domainMap));
  }
  m.A = A;
  m.factored = false;
  const auto gathered =
      Tpetra::importAndFillCompleteCrsMatrix<Matrix>(A, *m.rowsToRoot, m.rootMap, m.rootMap);

  // Rank 0: CRS arrays with global column ids (= local ids of serialMap), sorted in each row.
  int changed = patternChanged ? 1 : 0;
  std::vector<double> values;
  if (m.isRoot()) {
    const auto local = gathered->getLocalMatrixHost();
    const auto colMap = gathered->getColMap();
    std::vector<size_t> rowPtr(N + 1, 0);
    std::vector<LO> colInd(local.nnz());
    values.resize(local.nnz());
    std::vector<std::pair<LO, double>> row;
    for (size_t r = 0; r < N; ++r) {
      row.clear();
      for (auto k = local.graph.row_map(r); k < local.graph.row_map(r + 1); ++k)
        row.emplace_back(static_cast<LO>(colMap->getGlobalElement(local.graph.entries(k))),
                         local.values(k));
      std::sort(row.begin(), row.end());
      rowPtr[r + 1] = rowPtr[r] + row.size();
      for (size_t k = 0; k < row.size(); ++k) {
        colInd[rowPtr[r] + k] = row[k].first;
        values[rowPtr[r] + k] = row[k].second;
      }
    }
    if (m.solver.is_null() || rowPtr != m.rowPtr || colInd != m.colInd) changed = 1;
    m.rowPtr = std::move(rowPtr);
    m.colInd = std::move(colInd);
  }
  Teuchos::broadcast(*m.comm, 0, &changed);

  auto t0 = Clock::now();
  onRoot(*m.comm, "KLU2 analysis failed: ", "Amesos2 rejected the matrix", [&] {
    Teuchos::ArrayRCP<size_t> rowPtr(m.rowPtr.size());
    Teuchos::ArrayRCP<LO> colInd(m.colInd.size());
    Teuchos::ArrayRCP<double> vals(values.size());
    std::copy(m.rowPtr.begin(), m.rowPtr.end(), rowPtr.begin());
    std::copy(m.colInd.begin(), m.colInd.end(), colInd.begin());
    std::copy(values.begin(), values.end(), vals.begin());
    m.serialA = Teuchos::rcp(new Matrix(m.serialMap, m.serialMap, rowPtr, colInd, vals));
    m.serialA->fillComplete(m.serialMap, m.serialMap);
    if (changed) {
      m.solver = Amesos2::create<Matrix, MultiVector>("KLU2", m.serialA);
      m.solver->symbolicFactorization();
    } else {
      m.solver->setA(m.serialA, Amesos2::SYMBFACT);  // keeps the symbolic analysis
    }
  });
  if (changed) {
    ++stats_.analyses;
    stats_.analysisSeconds += secondsSince(t0);
  }
  t0 = Clock::now();
  onRoot(*m.comm, "KLU2 factorization failed: ",
         "the matrix is singular (KLU found a zero pivot, or ran out of memory)",
         [&] { m.solver->numericFactorization(); });
  m.factored = true;
  ++stats_.factorizations;
  stats_.factorizationSeconds += secondsSince(t0);
}

void Klu2Solver::solve(const MultiVector& b, MultiVector& x) {
  Impl& m = *impl_;
  if (!m.factored) throw LinearSolverError("KLU2 solve called before a successful setMatrix");
  const size_t nrhs = b.getNumVectors();
  if (x.getNumVectors() != nrhs)
    throw LinearSolverError("KLU2 solve: b and x have different numbers of columns");
  if (!b.getMap()->isSameAs(*m.rangeMap) || !x.getMap()->isSameAs(*m.domainMap))
    throw LinearSolverError("KLU2 solve: b and x must live on the matrix's range / domain map");
  if (nrhs == 0) return;
  const auto t0 = Clock::now();

  MultiVector root(m.rootMap, nrhs);
  root.doImport(b, *m.toRoot, Tpetra::INSERT);
  onRoot(*m.comm, "KLU2 solve failed: ", "Amesos2 could not solve", [&] {
    // Same local data, seen from the one-rank communicator.
    MultiVector serialB(m.serialMap, nrhs), serialX(m.serialMap, nrhs);
    for (size_t j = 0; j < nrhs; ++j) {
      const auto from = root.getData(j);
      std::copy(from.begin(), from.end(), serialB.getDataNonConst(j).begin());
    }
    m.solver->solve(Teuchos::ptrFromRef(serialX), Teuchos::ptrFromRef(serialB));
    for (size_t j = 0; j < nrhs; ++j) {
      const auto from = serialX.getData(j);
      std::copy(from.begin(), from.end(), root.getDataNonConst(j).begin());
    }
  });
  x.doImport(root, *m.fromRoot, Tpetra::INSERT);

  // Never trust the answer: r = b - A x against the caller's matrix.
  MultiVector r(b, Teuchos::Copy);
  m.A->apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
  std::vector<double> rNorm(nrhs), bNorm(nrhs);
  r.norm2(rNorm);
  b.norm2(bNorm);
  double worst = 0;
  for (size_t j = 0; j < nrhs; ++j)
    worst = std::max(worst, bNorm[j] > 0 ? rNorm[j] / bNorm[j] : rNorm[j]);
  stats_.relativeResidual = worst;
  ++stats_.solves;
  stats_.solveSeconds += secondsSince(t0);
  if (!(worst <= options_.residualTolerance))
    throw LinearSolverError("KLU2 returned a wrong solution: relative residual " +
                            formatNumber(worst) + " exceeds the Residual Tolerance " +
                            formatNumber(options_.residualTolerance));
}

}  // namespace contactlab
