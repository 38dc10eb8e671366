#include "linear/MatrixSnapshot.hpp"

#include <algorithm>

namespace contactlab {

void MatrixSnapshot::sortedRow(const Matrix::local_matrix_host_type& local, const Map& colMap,
                               LO row, std::vector<std::pair<GO, double>>& out) {
  out.clear();
  for (auto k = local.graph.row_map(row); k < local.graph.row_map(row + 1); ++k)
    out.emplace_back(colMap.getGlobalElement(local.graph.entries(k)), local.values(k));
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
}

MatrixSnapshot::MatrixSnapshot(const Matrix& A) : globalRows_(A.getGlobalNumRows()) {
  const auto rowMap = A.getRowMap();
  const LO n = static_cast<LO>(A.getNodeNumRows());
  rows_.resize(n);
  rowStart_.assign(1, 0);
  rowStart_.reserve(n + 1);
  cols_.reserve(A.getNodeNumEntries());
  values_.reserve(A.getNodeNumEntries());
  const auto local = A.getLocalMatrixHost();
  std::vector<std::pair<GO, double>> row;
  for (LO r = 0; r < n; ++r) {
    rows_[r] = rowMap->getGlobalElement(r);
    sortedRow(local, *A.getColMap(), r, row);
    for (const auto& [col, value] : row) {
      cols_.push_back(col);
      values_.push_back(value);
    }
    rowStart_.push_back(cols_.size());
  }
}

bool MatrixSnapshot::sameRowsAs(const Matrix& A) const {
  if (empty() || A.getGlobalNumRows() != globalRows_ || A.getNodeNumRows() != rows_.size())
    return false;
  const auto rowMap = A.getRowMap();
  for (size_t r = 0; r < rows_.size(); ++r)
    if (rowMap->getGlobalElement(static_cast<LO>(r)) != rows_[r]) return false;
  return true;
}

MatrixSnapshot::Difference MatrixSnapshot::differenceFrom(const Matrix& A) const {
  Difference d;
  const auto local = A.getLocalMatrixHost();
  std::vector<std::pair<GO, double>> row;
  for (size_t r = 0; r < rows_.size(); ++r) {
    sortedRow(local, *A.getColMap(), static_cast<LO>(r), row);
    // Merge the new row with the snapshot's, both sorted by column.
    size_t k = rowStart_[r];
    const size_t end = rowStart_[r + 1];
    auto differs = [&](GO col, double delta) {
      if (delta != 0.0) d.entries.push_back({rows_[r], col, delta});
    };
    for (const auto& [col, value] : row) {
      for (; k < end && cols_[k] < col; ++k)
        differs(cols_[k], -values_[k]);
      if (k < end && cols_[k] == col) {
        differs(col, value - values_[k]);
        ++k;
      } else {
        differs(col, value);
      }
    }
    for (; k < end; ++k)
      differs(cols_[k], -values_[k]);
  }
  d.indices.reserve(2 * d.entries.size());
  for (const auto& e : d.entries) {
    d.indices.push_back(e.row);
    d.indices.push_back(e.col);
  }
  std::sort(d.indices.begin(), d.indices.end());
  d.indices.erase(std::unique(d.indices.begin(), d.indices.end()), d.indices.end());
  return d;
}

}  // namespace contactlab
