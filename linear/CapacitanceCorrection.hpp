#pragma once
// Solves A x = b with the factors of a reference matrix A0 when A - A0 = P D P^T, P the columns
// of the identity on a small index set J and D = P^T (A - A0) P (a few nonzeros):
//   (I + G D) y = P^T A0^-1 b,   x = A0^-1 (b - P D y),   G = P^T A0^-1 P,
// the Sherman-Morrison-Woodbury identity in its capacitance form, which never inverts D (a
// contact term's D is singular). Proof: A x = b <=> x = A0^-1 (b - P D P^T x); with y = P^T x,
// y = P^T A0^-1 b - G D y. A solve then costs two solves with A0 and the solve of a dense
// |J| x |J| system whose LU replaces a factorization of A.
//
// This class is the dense part, on one process: the entries of G come from the caller (a
// direct solver's entries of A0^-1) and are kept for every index met since the reference, so
// that a later matrix whose changes stay among them needs no new entry. Global indices are
// the positions in the caller's full-length vectors.
#include "base/LinearAlgebra.hpp"
#include "linear/MatrixSnapshot.hpp"

#include <unordered_map>
#include <utility>
#include <vector>

namespace contactlab {

class CapacitanceCorrection {
 public:
  // symmetric: A0 is symmetric, so G is, and only one triangle of new entries is fetched.
  explicit CapacitanceCorrection(bool symmetric) : symmetric_(symmetric) {}

  // Forgets every index and entry: for a new reference matrix.
  void reset();
  // The entries of A0^-1 that adding `newIndices` needs, as (column, row) sorted by column then
  // row: every known or new row of the new columns and, unless symmetric, the new rows of the
  // known columns.
  std::vector<std::pair<GO, GO>> entriesToFetch(const std::vector<GO>& newIndices) const;
  // Adds `newIndices` with the values of entriesToFetch(newIndices), in its order.
  void addIndices(const std::vector<GO>& newIndices, const std::vector<double>& values);

  // Factors I + G D for J = `indices` (sorted, unique, all known) and D's entries (global row
  // and column in J). Returns false when I + G D is singular to working precision (a zero
  // pivot, or a condition estimate beyond kSingularConditionBound): A may then be singular,
  // and only its own factorization can say.
  bool factor(const std::vector<GO>& indices, const std::vector<MatrixSnapshot::Entry>& delta);
  // b := b - P D y, y solving (I + G D) y = P^T x0, for x0 = A0^-1 b (both of full length).
  void correct(const double* x0, double* b) const;

 private:
  const bool symmetric_;
  // G on the known indices: column c's entries of rows 0..known_.size() - 1 (rows added later
  // extend every column).
  std::vector<GO> known_;
  std::unordered_map<GO, size_t> position_;
  std::vector<std::vector<double>> columns_;
  // The factored system.
  std::vector<GO> indices_;
  struct LocalEntry {
    int row;
    int col;
    double value;
  };
  std::vector<LocalEntry> delta_;
  std::vector<double> lu_;  // column major, |J| x |J|
  std::vector<int> pivots_;
};

}  // namespace contactlab
