#include "linear/MatrixSnapshot.hpp"

#include <algorithm>

namespace contactlab {

namespace {

bool byColumn(const std::pair<GO, double>& a, const std::pair<GO, double>& b) {
  return a.first < b.first;
}

}  // namespace

MatrixSnapshot::MatrixSnapshot(const Matrix& A)
    : globalRows_(A.getGlobalNumRows()), colMap_(A.getColMap()) {
  const auto rowMap = A.getRowMap();
  const LO n = static_cast<LO>(A.getNodeNumRows());
  const auto local = A.getLocalMatrixHost();
  rows_.resize(n);
  for (LO r = 0; r < n; ++r)
    rows_[r] = rowMap->getGlobalElement(r);
  rowStart_.assign(local.graph.row_map.data(), local.graph.row_map.data() + n + 1);
  const size_t entries = rowStart_.back();
  cols_.assign(local.graph.entries.data(), local.graph.entries.data() + entries);
  values_.assign(local.values.data(), local.values.data() + entries);
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
                                                          size_t maxIndices) const {
  Difference d;
  const auto local = A.getLocalMatrixHost();
  const Map& colMap = *A.getColMap();
  // Local column indices mean the same columns on both sides (this rank's part only).
  const bool sameColumns = colMap_.get() == &colMap || colMap_->locallySameAs(colMap);
  // The distinct indices as they come, marked by A's local column (a row is a column of a
  // square matrix; an index outside A's columns, an entry that left the pattern, is kept
  // apart): the scan stops as soon as there are more than maxIndices of them.
  std::vector<char> marked(colMap.getNodeNumElements(), 0);
  std::vector<GO> outside;
  auto mark = [&](GO gid, LO lid) {
    if (lid == Teuchos::OrdinalTraits<LO>::invalid()) {
      outside.push_back(gid);
    } else if (!marked[lid]) {
      marked[lid] = 1;
      d.indices.push_back(gid);
    }
  };
  std::vector<std::pair<GO, double>> row, old;
  for (size_t r = 0; r < rows_.size(); ++r) {
    const size_t begin = rowStart_[r], end = rowStart_[r + 1];
    const size_t aBegin = local.graph.row_map(r), aEnd = local.graph.row_map(r + 1);
    const size_t before = d.entries.size();
    bool samePattern = sameColumns && aEnd - aBegin == end - begin;
    for (size_t k = 0; samePattern && k < end - begin; ++k)
      samePattern = local.graph.entries(aBegin + k) == cols_[begin + k];
    if (samePattern) {  // the usual case: the entries side by side
      for (size_t k = 0; k < end - begin; ++k) {
        const double delta = local.values(aBegin + k) - values_[begin + k];
        if (delta == 0.0) continue;
        const GO col = colMap.getGlobalElement(cols_[begin + k]);
        d.entries.push_back({rows_[r], col, delta});
        mark(col, cols_[begin + k]);
      }
    } else {  // a changed pattern: merge the rows sorted by global column
      row.clear();
      for (size_t k = aBegin; k < aEnd; ++k)
        row.emplace_back(colMap.getGlobalElement(local.graph.entries(k)), local.values(k));
      old.clear();
      for (size_t k = begin; k < end; ++k)
        old.emplace_back(colMap_->getGlobalElement(cols_[k]), values_[k]);
      std::sort(row.begin(), row.end(), byColumn);
      std::sort(old.begin(), old.end(), byColumn);
      auto differs = [&](GO col, double delta) {
        if (delta == 0.0) return;
        d.entries.push_back({rows_[r], col, delta});
        mark(col, colMap.getLocalElement(col));
      };
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
    if (d.entries.size() == before) continue;
    mark(rows_[r], colMap.getLocalElement(rows_[r]));
    if (d.indices.size() + outside.size() > maxIndices) {
      d.exceeded = true;
      return d;
    }
  }
  d.indices.insert(d.indices.end(), outside.begin(), outside.end());
  std::sort(d.indices.begin(), d.indices.end());
  d.indices.erase(std::unique(d.indices.begin(), d.indices.end()), d.indices.end());
  return d;
}

}  // namespace contactlab
