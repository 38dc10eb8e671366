#pragma once
// Assembly of element matrices into the tangent: a Tpetra matrix over the owned dofs whose
// graph is built once. Rows this rank owns are written straight into the matrix's CRS values
// through offsets found once per element (no column search per entry). Rows owned by another
// rank (ghost rows, only on elements at a partition boundary) go to a small ghost matrix that
// end() exports (ADD) into the owners' rows.
//
// Dofs are those of DofMap: overlap LIDs node * dim + component, owned nodes first, so an
// owned overlap LID is also the matrix's local row.
#include "base/LinearAlgebra.hpp"
#include "core/problem/DofMap.hpp"

#include <Teuchos_RCP.hpp>

#include <vector>

namespace contactlab {

class MatrixAssembler {
 public:
  // elementNodes[e]: overlap node indices of local element e. extraGraphNodes[e] (empty, or one
  // list per element): further overlap nodes the graph couples to e's nodes and to each other,
  // where a constraint moves rows and columns (LinearConstraints::partnerNodes); no element
  // matrix writes there.
  MatrixAssembler(const DofMap& dofs, const std::vector<std::vector<int>>& elementNodes,
                  const std::vector<std::vector<int>>& extraGraphNodes = {});

  const Teuchos::RCP<Matrix>& matrix() const { return matrix_; }

  // Zeroes the matrix and opens it for additions.
  void begin();
  // Adds element e's matrix (row major, dim * nodes squared), skipping the rows and columns of
  // dofs flagged in `constrained` (indexed by overlap LID).
  void add(std::size_t e, const double* ke, const std::vector<char>& constrained);
  // Same for a matrix over some of element e's nodes (a facet of it: its entries are in e's
  // graph pattern): node a of the matrix is node nodes[a] of the element's list, k is row
  // major, (nodes.size() * dim)^2.
  void add(std::size_t e, const std::vector<int>& nodes, const double* k,
           const std::vector<char>& constrained);
  // Adds `value` to the diagonal of an owned row.
  void addDiagonal(LO row, double value);
  // Sends ghost rows to their owners and closes the matrix.
  void end();

  // Keeps the values added since begin() (owned and ghost rows), so that a later assembly of
  // the same element matrices starts from them (beginFromKept) instead of adding them again:
  // a solid whose tangent does not change (Problem::assemble).
  void keepValues();
  bool keepsValues() const { return kept_; }
  // begin(), with the kept values instead of zeros.
  void beginFromKept();

 private:
  // add() over the element's nodes local(0), ..., local(m - 1).
  template <class Local>
  void addRows(std::size_t e, int m, Local local, const double* k,
               const std::vector<char>& constrained);

  int dim_;
  LO ownedDofs_;
  std::vector<std::vector<int>> elementNodes_;
  // offsets_[e][a * n + b]: position of column (b, 0) in row (a, 0) relative to the row's start;
  // -1 when node a is a ghost. Rows (a, c) share the pattern of (a, 0).
  std::vector<std::vector<int>> offsets_;
  // ghostColumns_[e][j]: ghost matrix column LID of element dof j.
  std::vector<std::vector<LO>> ghostColumns_;
  Teuchos::RCP<Matrix> matrix_, ghostMatrix_;
  Teuchos::RCP<Export> ghostExporter_;
  bool ghostsAnywhere_ = false;
  double* values_ = nullptr;
  const std::size_t* rowStart_ = nullptr;
  bool kept_ = false;
  std::vector<double> keptValues_, keptGhostValues_;
};

}  // namespace contactlab
