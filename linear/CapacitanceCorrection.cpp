#include "linear/CapacitanceCorrection.hpp"

#include "linear/LinearSolver.hpp"

#include <Teuchos_LAPACK.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace contactlab {

void CapacitanceCorrection::reset() {
  known_.clear();
  position_.clear();
  columns_.clear();
  indices_.clear();
  delta_.clear();
  lu_.clear();
  pivots_.clear();
}

std::vector<std::pair<GO, GO>> CapacitanceCorrection::entriesToFetch(
    const std::vector<GO>& newIndices) const {
  std::vector<GO> rows = known_;
  rows.insert(rows.end(), newIndices.begin(), newIndices.end());
  std::sort(rows.begin(), rows.end());
  std::vector<std::pair<GO, GO>> out;
  out.reserve(newIndices.size() * rows.size() +
              (symmetric_ ? 0 : known_.size() * newIndices.size()));
  for (GO c : newIndices)
    for (GO r : rows)
      out.emplace_back(c, r);
  if (!symmetric_)
    for (GO c : known_)
      for (GO r : newIndices)
        out.emplace_back(c, r);
  std::sort(out.begin(), out.end());
  return out;
}

void CapacitanceCorrection::addIndices(const std::vector<GO>& newIndices,
                                       const std::vector<double>& values) {
  const auto fetched = entriesToFetch(newIndices);
  if (fetched.size() != values.size())
    throw std::logic_error("CapacitanceCorrection::addIndices: " + std::to_string(values.size()) +
                           " values for " + std::to_string(fetched.size()) + " entries");
  const size_t oldCount = known_.size();
  for (GO i : newIndices) {
    position_[i] = known_.size();
    known_.push_back(i);
  }
  const size_t count = known_.size();
  for (auto& column : columns_)
    column.resize(count, 0.0);
  columns_.resize(count, std::vector<double>(count, 0.0));
  for (size_t k = 0; k < fetched.size(); ++k) {
    const auto& [col, row] = fetched[k];
    columns_[position_.at(col)][position_.at(row)] = values[k];
  }
  if (symmetric_)  // the known columns' new rows, by symmetry
    for (size_t c = 0; c < oldCount; ++c)
      for (size_t r = oldCount; r < count; ++r)
        columns_[c][r] = columns_[r][c];
}

bool CapacitanceCorrection::factor(const std::vector<GO>& indices,
                                   const std::vector<MatrixSnapshot::Entry>& delta) {
  indices_ = indices;
  const int n = static_cast<int>(indices_.size());
  std::unordered_map<GO, int> local;
  for (int i = 0; i < n; ++i)
    local[indices_[i]] = i;
  delta_.clear();
  delta_.reserve(delta.size());
  for (const auto& e : delta)
    delta_.push_back({local.at(e.row), local.at(e.col), e.value});
  // C = I + G D: column q gets D(p, q) times G's column p (restricted to J).
  lu_.assign(static_cast<size_t>(n) * n, 0.0);
  for (int i = 0; i < n; ++i)
    lu_[static_cast<size_t>(i) * n + i] = 1.0;
  std::vector<size_t> knownPosition(n);
  for (int i = 0; i < n; ++i)
    knownPosition[i] = position_.at(indices_[i]);
  for (const auto& e : delta_) {
    const auto& g = columns_[knownPosition[e.row]];
    double* c = &lu_[static_cast<size_t>(e.col) * n];
    for (int i = 0; i < n; ++i)
      c[i] += e.value * g[knownPosition[i]];
  }
  pivots_.assign(n, 0);
  if (n == 0) return true;
  const Teuchos::LAPACK<int, double> lapack;
  std::vector<double> work(4 * static_cast<size_t>(n));
  std::vector<int> iwork(n);
  double norm = 0;  // the 1-norm, GECON's input
  for (int j = 0; j < n; ++j) {
    double column = 0;
    for (int i = 0; i < n; ++i)
      column += std::abs(lu_[static_cast<size_t>(j) * n + i]);
    norm = std::max(norm, column);
  }
  int info = 0;
  lapack.GETRF(n, n, lu_.data(), n, pivots_.data(), &info);
  if (info != 0) return false;
  // A singular A makes I + G D singular, but its LU rarely meets an exact zero pivot, and the
  // residual check cannot tell: a zero row of A leaves a residual independent of x. The
  // condition estimate can: beyond the bound that proves a matrix singular, refuse.
  double rcond = 0;
  lapack.GECON('1', n, lu_.data(), n, norm, &rcond, work.data(), iwork.data(), &info);
  return info == 0 && rcond * kSingularConditionBound > 1.0;
}

void CapacitanceCorrection::correct(const double* x0, double* b) const {
  const int n = static_cast<int>(indices_.size());
  if (n == 0) return;
  std::vector<double> y(n);
  for (int i = 0; i < n; ++i)
    y[i] = x0[indices_[i]];
  int info = 0;
  Teuchos::LAPACK<int, double>().GETRS('N', n, 1, lu_.data(), n, pivots_.data(), y.data(), n,
                                       &info);
  for (const auto& e : delta_)
    b[indices_[e.row]] -= e.value * y[e.col];
}

}  // namespace contactlab
