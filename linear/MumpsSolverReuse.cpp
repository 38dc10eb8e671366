// MumpsSolver's factorization reuse: a matrix equal to the last factorized one is solved with
// its factors; one that differs from it on few rows and columns, through a low-rank correction
// of them (CapacitanceCorrection), when that is predicted cheaper than a factorization. A
// corrected solve is checked by A's residual and refined (MumpsSolverPrecision.cpp).
#include "base/Elapsed.hpp"
#include "linear/IterativeRefinement.hpp"
#include "linear/MumpsSolverImpl.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <numeric>
#include <type_traits>

namespace contactlab {

namespace {

using Clock = std::chrono::steady_clock;

// Costs in factorization flops (which run dense BLAS 3 kernels) per flop of a pass over the
// factors: a solve with one right-hand side is memory-bound (weight 24), the entries of the
// inverse come in blocks of columns with the elimination tree pruned (1 per column). Measured
// on hertz-3d tet10, 46 572 dofs: a factorization 2.2 s for 5.7e10 flops, a solve 0.066 s, the
// 1 746 columns of a first correction 4.7 s, for 3.7e7 factor entries (doc/performance.md,
// "Factorization reuse"). The decision uses flop counts, not timings, so that a run takes the
// same path, hence has the same round-off, on a loaded machine.
constexpr double kSolveWeight = 24.0;
constexpr double kInverseColumnWeight = 1.0;
// A correction's inverse entries serve every later matrix that differs from the reference on
// the same indices (the next Newton iterations and load steps of a solid whose tangent is
// constant): it is taken when it costs less than this many factorizations.
constexpr double kAmortization = 2.0;
constexpr MUMPS_INT kInverseColumnBlock = 256;

// Whether solving through a correction of `rank` indices, `fresh` of them without entries of
// the inverse yet, is predicted to pay: the new columns of the inverse, the dense LU and the
// second solve each iteration then needs, against kAmortization factorizations.
bool correctionPays(size_t rank, size_t fresh, double factorFlops, double factorEntries) {
  const double pass = 2.0 * factorEntries;  // flops of one pass over the factors
  const double r = static_cast<double>(rank);
  const double predicted = kInverseColumnWeight * pass * static_cast<double>(fresh) +
                           kSolveWeight * pass + 2.0 / 3.0 * r * r * r;
  return predicted < kAmortization * factorFlops;
}

// The sorted union of every rank's sorted `local` indices, on every rank.
std::vector<GO> unionOverRanks(const std::vector<GO>& local, MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  int count = static_cast<int>(local.size());
  std::vector<int> counts(size), offsets(size, 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  std::partial_sum(counts.begin(), counts.end() - 1, offsets.begin() + 1);
  std::vector<GO> all(offsets.back() + counts.back());
  MPI_Allgatherv(local.data(), count, MPI_LONG_LONG, all.data(), counts.data(), offsets.data(),
                 MPI_LONG_LONG, comm);
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

// Every rank's entries on rank 0 (as row, column, value triples of doubles: global ids are
// below 2^31, exact in a double).
std::vector<MatrixSnapshot::Entry> gatherOnRoot(const std::vector<MatrixSnapshot::Entry>& local,
                                                MPI_Comm comm) {
  int size = 1, rank = 0;
  MPI_Comm_size(comm, &size);
  MPI_Comm_rank(comm, &rank);
  std::vector<double> packed;
  packed.reserve(3 * local.size());
  for (const auto& e : local) {
    packed.push_back(static_cast<double>(e.row));
    packed.push_back(static_cast<double>(e.col));
    packed.push_back(e.value);
  }
  int count = static_cast<int>(packed.size());
  std::vector<int> counts(size), offsets(size, 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  std::partial_sum(counts.begin(), counts.end() - 1, offsets.begin() + 1);
  std::vector<double> all(rank == 0 ? offsets.back() + counts.back() : 0);
  MPI_Gatherv(packed.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
              MPI_DOUBLE, 0, comm);
  std::vector<MatrixSnapshot::Entry> entries(all.size() / 3);
  for (size_t k = 0; k < entries.size(); ++k)
    entries[k] = {static_cast<GO>(all[3 * k]), static_cast<GO>(all[3 * k + 1]), all[3 * k + 2]};
  return entries;
}

}  // namespace

bool MumpsSolver::reusesFactorization() const {
  return options_.reuseFactorization && !options_.determinant && !options_.conditionEstimate;
}

void MumpsSolver::keepReference(const Matrix& A) {
  Impl& m = *impl_;
  m.correctionIndices.clear();
  m.correction.reset();
  // Every size is compared: on the 2D Hertz scene (3 898 unknowns, factorizations of a few
  // milliseconds) corrections still halve the linear solves (10 factorizations -> 2 and 7
  // corrections), and the snapshot costs one pass over the entries (doc/performance.md).
  m.reference = reusesFactorization() ? MatrixSnapshot(A) : MatrixSnapshot();
}

bool MumpsSolver::correctFrom(const Teuchos::RCP<const Matrix>& A) {
  Impl& m = *impl_;
  const auto t0 = Clock::now();
  int same = m.reference.sameRowsAs(*A) ? 1 : 0;
  int allSame = 0;
  MPI_Allreduce(&same, &allSame, 1, MPI_INT, MPI_MIN, m.comm);
  if (!allSame) return false;
  // A rank's distinct changed rows and columns bound the rank from below: past Max Correction
  // Rank of them on a rank, the scan stops, and A is factorized.
  const size_t maxRank = static_cast<size_t>(options_.maxCorrectionRank);
  const auto difference = m.reference.differenceFrom(*A, maxRank);
  int exceeded = difference.exceeded ? 1 : 0;
  int anyExceeded = 0;
  MPI_Allreduce(&exceeded, &anyExceeded, 1, MPI_INT, MPI_MAX, m.comm);
  if (anyExceeded) return false;
  const std::vector<GO> indices = unionOverRanks(difference.indices, m.comm);
  if (indices.empty()) {  // the factorized matrix itself
    m.correcting = false;
    m.current = A;
    if (m.singleFactors) m.currentNormInf = normInf(*A);  // its solves are refined
    ++stats_.reusedFactorizations;
    stats_.correctionSeconds += secondsSince(t0);
    return true;
  }
  std::vector<GO> fresh;
  std::set_difference(indices.begin(), indices.end(), m.correctionIndices.begin(),
                      m.correctionIndices.end(), std::back_inserter(fresh));
  // The rank bounds the dense LU, the known indices the inverse entries kept (G).
  if (indices.size() > maxRank || m.correctionIndices.size() + fresh.size() > 2 * maxRank)
    return false;
  if (!correctionPays(indices.size(), fresh.size(), m.referenceFlops, m.referenceEntries))
    return false;

  if (m.isRoot() && !m.correction)
    m.correction = std::make_unique<CapacitanceCorrection>(options_.mode != Mode::general);
  if (!fresh.empty()) {
    std::vector<std::pair<GO, GO>> entries;
    if (m.isRoot()) entries = m.correction->entriesToFetch(fresh);
    const std::vector<double> values = inverseEntries(entries);
    if (m.isRoot()) m.correction->addIndices(fresh, values);
    std::vector<GO> known;
    std::merge(m.correctionIndices.begin(), m.correctionIndices.end(), fresh.begin(), fresh.end(),
               std::back_inserter(known));
    m.correctionIndices = std::move(known);
  }
  const auto delta = gatherOnRoot(difference.entries, m.comm);
  int factored = m.isRoot() ? (m.correction->factor(indices, delta) ? 1 : 0) : 0;
  MPI_Bcast(&factored, 1, MPI_INT, 0, m.comm);
  // A zero pivot: A is singular, or the correction cannot tell; the factorization will say.
  if (!factored) return false;
  m.currentNormInf = normInf(*A);
  m.correcting = true;
  m.current = A;
  ++stats_.reusedFactorizations;
  ++stats_.corrections;
  stats_.lastCorrectionRank = static_cast<int>(indices.size());
  stats_.correctionSeconds += secondsSince(t0);
  return true;
}

std::vector<double> MumpsSolver::inverseEntries(const std::vector<std::pair<GO, GO>>& entries) {
  Impl& m = *impl_;
  return m.withFactors([&](auto& mumps) {
    using Real = typename std::decay_t<decltype(mumps)>::Real;
    std::vector<MUMPS_INT> pointers, rows;
    std::vector<Real> values;
    if (m.isRoot()) {
      // Compressed columns, 1-based, over all N columns (MUMPS asks NRHS = N).
      const MUMPS_INT n = mumps.id.n;
      pointers.assign(n + 1, 0);
      for (const auto& entry : entries)
        ++pointers[entry.first + 1];
      std::partial_sum(pointers.begin(), pointers.end(), pointers.begin());
      for (auto& p : pointers)
        ++p;
      rows.reserve(entries.size());
      for (const auto& entry : entries)
        rows.push_back(static_cast<MUMPS_INT>(entry.second + 1));
      values.assign(entries.size(), Real(0));
      mumps.id.nrhs = n;
      mumps.id.nz_rhs = static_cast<MUMPS_INT>(entries.size());
      mumps.id.irhs_ptr = pointers.data();
      mumps.id.irhs_sparse = rows.data();
      mumps.id.rhs_sparse = values.data();
    }
    mumps.icntl(30) = 1;
    // Columns of the inverse in blocks of 256 (ICNTL(27)) rather than MUMPS' default of about
    // 32: the 1 712 columns of the first correction of hertz-3d tet10 at 130 000 unknowns in
    // 0.79 times the time (23.5 s against 29.8 s for the run's corrections), memory unchanged.
    const MUMPS_INT blocking = mumps.icntl(27);
    mumps.icntl(27) = kInverseColumnBlock;
    mumps.run(3);
    mumps.icntl(27) = blocking;
    mumps.icntl(30) = 0;
    mumps.id.irhs_ptr = nullptr;
    mumps.id.irhs_sparse = nullptr;
    mumps.id.rhs_sparse = nullptr;
    mumps.check("computation of entries of the inverse");
    return std::vector<double>(values.begin(), values.end());
  });
}

void MumpsSolver::solveCentralized(MultiVector& root) {
  Impl& m = *impl_;
  const size_t nrhs = root.getNumVectors();
  if (!m.singleFactors) {
    Teuchos::ArrayRCP<double> data;
    if (m.isRoot()) {
      data = root.get1dViewNonConst();
      m.dbl.id.rhs = data.getRawPtr();
      m.dbl.id.lrhs = static_cast<MUMPS_INT>(std::max<size_t>(root.getStride(), 1));
    }
    m.dbl.id.nrhs = static_cast<MUMPS_INT>(nrhs);
    m.dbl.run(3);
    m.dbl.id.rhs = nullptr;
    m.dbl.check("solve");
    return;
  }
  // Single factors: each column scaled by its largest entry (the refinement's residuals
  // shrink by decades, single precision's range does not follow), rounded, solved, scaled back.
  const size_t n = m.isRoot() ? root.getLocalLength() : 0;
  std::vector<float> buffer(n * nrhs);
  std::vector<double> scales(nrhs, 1.0);
  if (m.isRoot()) {
    for (size_t j = 0; j < nrhs; ++j) {
      const auto column = root.getData(j);
      double largest = 0;
      for (size_t i = 0; i < n; ++i)
        largest = std::max(largest, std::abs(column[i]));
      if (largest > 0) scales[j] = largest;
      for (size_t i = 0; i < n; ++i)
        buffer[j * n + i] = static_cast<float>(column[i] / scales[j]);
    }
    m.sgl->id.rhs = buffer.data();
    m.sgl->id.lrhs = static_cast<MUMPS_INT>(std::max<size_t>(n, 1));
  }
  m.sgl->id.nrhs = static_cast<MUMPS_INT>(nrhs);
  m.sgl->run(3);
  m.sgl->id.rhs = nullptr;
  m.sgl->check("solve");
  for (size_t j = 0; j < nrhs && m.isRoot(); ++j) {
    auto column = root.getDataNonConst(j);
    for (size_t i = 0; i < n; ++i)
      column[i] = scales[j] * static_cast<double>(buffer[j * n + i]);
  }
}

void MumpsSolver::solveCorrected(const MultiVector& b, MultiVector& x) {
  Impl& m = *impl_;
  const size_t nrhs = b.getNumVectors();
  MultiVector root(m.rootMap, nrhs);
  root.doImport(b, *m.toRoot, Tpetra::INSERT);
  MultiVector corrected(m.rootMap, nrhs);
  corrected.assign(root);
  solveCentralized(root);  // A0^-1 b
  if (m.isRoot())
    for (size_t j = 0; j < nrhs; ++j)
      m.correction->correct(root.getData(j).getRawPtr(), corrected.getDataNonConst(j).getRawPtr());
  solveCentralized(corrected);  // A0^-1 (b - P D y)
  x.doImport(corrected, *m.fromRoot, Tpetra::INSERT);
}

}  // namespace contactlab
