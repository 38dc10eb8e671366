#pragma once
// A copy of the values of a distributed matrix's local rows, and the difference of another
// matrix from it: the rows and columns where any entry differs (exactly: an unchanged entry is
// bitwise equal when it was assembled from the same inputs) and the entries of the difference
// on them. Entries absent from one pattern count as zero, so two matrices with different
// patterns (contact terms added) compare entry by entry. Local work only: the caller gathers
// the indices over the ranks.
//
// The copy keeps the local (CSR) indices with the column map: a snapshot and a comparison
// against a matrix on the same column map and row pattern (every Newton iteration between two
// pairings) are plain passes over the values; global column ids are looked up only for the
// entries that differ, and for the rows whose pattern changed.
#include "base/LinearAlgebra.hpp"

#include <vector>

namespace contactlab {

class MatrixSnapshot {
 public:
  struct Entry {
    GO row;
    GO col;
    double value;
  };
  struct Difference {
    std::vector<GO> indices;     // sorted, unique: rows of this rank and columns that differ
    std::vector<Entry> entries;  // (A - snapshot) on this rank's rows, nonzero entries only
    bool exceeded = false;       // more rows changed than asked for: the scan stopped there
  };

  MatrixSnapshot() = default;
  explicit MatrixSnapshot(const Matrix& A);

  bool empty() const { return rowStart_.empty(); }
  // Whether A has this snapshot's global size and the same rows on this rank, in the same
  // order (a collective answer is the caller's: reduce it over the ranks).
  bool sameRowsAs(const Matrix& A) const;
  // A - snapshot; A must have the same rows (sameRowsAs). Stops (exceeded) as soon as more than
  // maxIndices distinct rows and columns differ on this rank: a matrix that changed everywhere
  // (a plastic or finite-strain solid) costs a few rows' comparison, not a pass over A.
  Difference differenceFrom(const Matrix& A, size_t maxIndices) const;

 private:
  Tpetra::global_size_t globalRows_ = 0;
  std::vector<GO> rows_;            // global ids of the local rows, in local order
  Teuchos::RCP<const Map> colMap_;  // of the local column indices below
  std::vector<size_t> rowStart_;    // CSR over rows_, each row in A's local order
  std::vector<LO> cols_;            // local column indices
  std::vector<double> values_;
};

}  // namespace contactlab
