#include "linear/MatrixSnapshot.hpp"

#include <algorithm>

namespace contactlab {

namespace {

bool byColumn(const std::pair<GO, double>& a, const std::pair<GO, double>& b) {
  return a.first < b.first;
}

}  // namespace

void MatrixSnapshot::rowOf(const Matrix::local_matrix_host_type& local, const Map& colMap, LO row,
                           std::vector<std::pair<GO, double>>& out) {
  out.clear();
  for (auto k = local.graph.row_map(row); k < local.graph.row_map(row + 1); ++k)
    out.emplace_back(colMap.getGlobalElement(local.graph.entries(k)), local.values(k));
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
    rowOf(local, *A.getColMap(), r, row);
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

MatrixSnapshot::Difference MatrixSnapshot::differenceFrom(const Matrix& A,
                                                          size_t maxChangedRows) const {
  Difference d;
  const auto local = A.getLocalMatrixHost();
  std::vector<std::pair<GO, double>> row, old;
  size_t changedRows = 0;
  for (size_t r = 0; r < rows_.size(); ++r) {
    rowOf(local, *A.getColMap(), static_cast<LO>(r), row);
    const size_t begin = rowStart_[r], end = rowStart_[r + 1];
    const size_t before = d.entries.size();
    auto differs = [&](GO col, double delta) {
      if (delta != 0.0) d.entries.push_back({rows_[r], col, delta});
    };
    bool samePattern = row.size() == end - begin;
    for (size_t k = 0; samePattern && k < row.size(); ++k)
      samePattern = row[k].first == cols_[begin + k];
    if (samePattern) {  // the usual case: the entries side by side
      for (size_t k = 0; k < row.size(); ++k)
        differs(row[k].first, row[k].second - values_[begin + k]);
    } else {  // a changed pattern: merge the rows sorted by column
      old.clear();
      for (size_t k = begin; k < end; ++k)
        old.emplace_back(cols_[k], values_[k]);
      std::sort(row.begin(), row.end(), byColumn);
      std::sort(old.begin(), old.end(), byColumn);
      auto o = old.begin();
      for (const auto& [col, value] : row) {
        for (; o != old.end() && o->first < col; ++o)
          differs(o->first, -o->second);
        if (o != old.end() && o->first == col) {
          differs(col, value - o->second);
          ++o;
        } else {
          differs(col, value);
        }
      }
      for (; o != old.end(); ++o)
        differs(o->first, -o->second);
    }
    if (d.entries.size() > before && ++changedRows > maxChangedRows) {
      d.exceeded = true;
      return d;
    }
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
