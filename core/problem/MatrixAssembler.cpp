#include "core/problem/MatrixAssembler.hpp"

#include <algorithm>
#include <stdexcept>

namespace contactlab {
namespace {

// Sorted unique neighbours (sharing an element, or its extra graph nodes) of every overlap node.
std::vector<std::vector<int>> nodeNeighbours(std::size_t numNodes,
                                             const std::vector<std::vector<int>>& elementNodes,
                                             const std::vector<std::vector<int>>& extra) {
  std::vector<std::vector<int>> neighbours(numNodes);
  std::vector<int> nodes;
  for (std::size_t e = 0; e < elementNodes.size(); ++e) {
    nodes = elementNodes[e];
    if (!extra.empty()) nodes.insert(nodes.end(), extra[e].begin(), extra[e].end());
    for (int a : nodes)
      neighbours[a].insert(neighbours[a].end(), nodes.begin(), nodes.end());
  }
  for (auto& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return neighbours;
}

}  // namespace

MatrixAssembler::MatrixAssembler(const DofMap& dofs,
                                 const std::vector<std::vector<int>>& elementNodes,
                                 const std::vector<std::vector<int>>& extraGraphNodes)
    : dim_(dofs.dim()),
      ownedDofs_(static_cast<LO>(dofs.numOwnedNodes() * dofs.dim())),
      elementNodes_(elementNodes) {
  const auto& overlapMap = dofs.overlapMap();
  const auto& ownedMap = dofs.ownedMap();
  const auto& comm = dofs.comm();
  const std::size_t numNodes = dofs.overlapNodes().size();
  const std::size_t ownedNodes = dofs.numOwnedNodes();
  const auto neighbours = nodeNeighbours(numNodes, elementNodes_, extraGraphNodes);
  auto gidOf = [&](int node, int c) {
    return overlapMap->getGlobalElement(static_cast<LO>(node * dim_ + c));
  };
  std::vector<GO> columns;
  auto rowColumns = [&](std::size_t node) {
    columns.clear();
    for (int m : neighbours[node])
      for (int c = 0; c < dim_; ++c)
        columns.push_back(gidOf(m, c));
    return Teuchos::ArrayView<const GO>(columns);
  };

  // Ghost rows: the overlap dofs of nodes this rank does not own.
  std::vector<GO> ghostGids;
  for (std::size_t n = ownedNodes; n < numNodes; ++n)
    for (int c = 0; c < dim_; ++c)
      ghostGids.push_back(gidOf(static_cast<int>(n), c));
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto ghostMap = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(ghostGids), 0, comm));
  std::vector<size_t> ghostLength;
  for (std::size_t n = ownedNodes; n < numNodes; ++n)
    ghostLength.insert(ghostLength.end(), dim_, neighbours[n].size() * dim_);
  auto ghostGraph =
      Teuchos::rcp(new Graph(ghostMap, Teuchos::ArrayView<const size_t>(ghostLength)));
  for (std::size_t n = ownedNodes; n < numNodes; ++n)
    for (int c = 0; c < dim_; ++c)
      ghostGraph->insertGlobalIndices(gidOf(n, c), rowColumns(n));
  ghostGraph->fillComplete(ownedMap, ownedMap);
  ghostsAnywhere_ = ghostMap->getGlobalNumElements() > 0;

  // Owned rows: this rank's elements plus what other ranks' ghost rows bring.
  std::vector<size_t> rowLength(ownedDofs_);
  for (std::size_t n = 0; n < ownedNodes; ++n)
    for (int c = 0; c < dim_; ++c)
      rowLength[n * dim_ + c] = neighbours[n].size() * dim_;
  auto ownedGraph = Teuchos::rcp(new Graph(ownedMap, Teuchos::ArrayView<const size_t>(rowLength)));
  for (std::size_t n = 0; n < ownedNodes; ++n)
    for (int c = 0; c < dim_; ++c)
      ownedGraph->insertGlobalIndices(gidOf(n, c), rowColumns(n));
  ghostExporter_ = Teuchos::rcp(new Export(ghostMap, ownedMap));
  if (ghostsAnywhere_) ownedGraph->doExport(*ghostGraph, *ghostExporter_, Tpetra::INSERT);
  ownedGraph->fillComplete(ownedMap, ownedMap);
  matrix_ = Teuchos::rcp(new Matrix(ownedGraph));
  ghostMatrix_ = Teuchos::rcp(new Matrix(ghostGraph));

  // Offsets of each element's columns in its owned rows, and ghost column LIDs.
  const auto local = matrix_->getLocalMatrixHost();
  const auto& rowMap = local.graph.row_map;
  const auto& entries = local.graph.entries;
  const auto colMap = matrix_->getColMap();
  const auto ghostColMap = ghostMatrix_->getColMap();
  offsets_.resize(elementNodes_.size());
  ghostColumns_.resize(elementNodes_.size());
  for (std::size_t e = 0; e < elementNodes_.size(); ++e) {
    const auto& nodes = elementNodes_[e];
    const int n = static_cast<int>(nodes.size());
    offsets_[e].assign(static_cast<std::size_t>(n) * n, -1);
    bool hasGhostRow = false;
    for (int a = 0; a < n; ++a) {
      if (nodes[a] >= static_cast<int>(ownedNodes)) {
        hasGhostRow = true;
        continue;
      }
      const LO row = nodes[a] * dim_;
      const auto begin = entries.data() + rowMap(row), end = entries.data() + rowMap(row + 1);
      for (int b = 0; b < n; ++b) {
        const LO col = colMap->getLocalElement(gidOf(nodes[b], 0));
        const auto it = std::lower_bound(begin, end, col);
        // The dim columns of a node are consecutive in every row of its dim rows.
        if (it == end || *it != col || it + dim_ > end || *(it + dim_ - 1) != col + dim_ - 1)
          throw std::logic_error("MatrixAssembler: unexpected matrix graph layout");
        offsets_[e][a * n + b] = static_cast<int>(it - begin);
      }
    }
    if (hasGhostRow) {
      for (int b = 0; b < n; ++b)
        for (int c = 0; c < dim_; ++c)
          ghostColumns_[e].push_back(ghostColMap->getLocalElement(gidOf(nodes[b], c)));
    }
  }
}

void MatrixAssembler::begin() {
  matrix_->resumeFill();
  matrix_->setAllToScalar(0.0);
  ghostMatrix_->resumeFill();
  ghostMatrix_->setAllToScalar(0.0);
  const auto local = matrix_->getLocalMatrixHost();
  values_ = local.values.data();
  rowStart_ = local.graph.row_map.data();
}

template <class Local>
void MatrixAssembler::addRows(std::size_t e, int m, Local local, const double* k,
                              const std::vector<char>& constrained) {
  const auto& nodes = elementNodes_[e];
  const int n = static_cast<int>(nodes.size());
  const int md = m * dim_;
  const int* offsets = offsets_[e].data();
  for (int a = 0; a < m; ++a) {
    const int la = local(a);
    for (int c = 0; c < dim_; ++c) {
      const int i = a * dim_ + c;
      const LO row = nodes[la] * dim_ + c;
      if (constrained[row]) continue;
      const double* kRow = k + static_cast<std::size_t>(i) * md;
      if (offsets[la * n] < 0) {  // ghost row
        thread_local std::vector<double> filtered;
        thread_local std::vector<LO> columns;
        filtered.assign(kRow, kRow + md);
        columns.resize(md);
        for (int b = 0; b < m; ++b)
          for (int kk = 0; kk < dim_; ++kk) {
            const int lb = local(b);
            columns[b * dim_ + kk] = ghostColumns_[e][lb * dim_ + kk];
            if (constrained[nodes[lb] * dim_ + kk]) filtered[b * dim_ + kk] = 0.0;
          }
        ghostMatrix_->sumIntoLocalValues(row - ownedDofs_, md, filtered.data(), columns.data());
        continue;
      }
      double* rowValues = values_ + rowStart_[row];
      for (int b = 0; b < m; ++b) {
        const int lb = local(b);
        double* target = rowValues + offsets[la * n + lb];
        const int colNode = nodes[lb] * dim_;
        for (int kk = 0; kk < dim_; ++kk)
          if (!constrained[colNode + kk]) target[kk] += kRow[b * dim_ + kk];
      }
    }
  }
}

void MatrixAssembler::add(std::size_t e, const double* ke, const std::vector<char>& constrained) {
  addRows(
      e, static_cast<int>(elementNodes_[e].size()), [](int a) { return a; }, ke, constrained);
}

void MatrixAssembler::add(std::size_t e, const std::vector<int>& nodes, const double* k,
                          const std::vector<char>& constrained) {
  addRows(
      e, static_cast<int>(nodes.size()), [&nodes](int a) { return nodes[a]; }, k, constrained);
}

void MatrixAssembler::addDiagonal(LO row, double value) {
  const LO col = matrix_->getColMap()->getLocalElement(matrix_->getRowMap()->getGlobalElement(row));
  matrix_->sumIntoLocalValues(row, 1, &value, &col);
}

void MatrixAssembler::keepValues() {
  const auto local = matrix_->getLocalMatrixHost();
  keptValues_.assign(local.values.data(), local.values.data() + local.values.extent(0));
  const auto ghost = ghostMatrix_->getLocalMatrixHost();
  keptGhostValues_.assign(ghost.values.data(), ghost.values.data() + ghost.values.extent(0));
  kept_ = true;
}

void MatrixAssembler::beginFromKept() {
  if (!kept_) throw std::logic_error("MatrixAssembler::beginFromKept: no values kept");
  matrix_->resumeFill();
  ghostMatrix_->resumeFill();
  const auto local = matrix_->getLocalMatrixHost();
  std::copy(keptValues_.begin(), keptValues_.end(), local.values.data());
  const auto ghost = ghostMatrix_->getLocalMatrixHost();
  std::copy(keptGhostValues_.begin(), keptGhostValues_.end(), ghost.values.data());
  values_ = local.values.data();
  rowStart_ = local.graph.row_map.data();
}

void MatrixAssembler::end() {
  ghostMatrix_->fillComplete(matrix_->getDomainMap(), matrix_->getRangeMap());
  if (ghostsAnywhere_) matrix_->doExport(*ghostMatrix_, *ghostExporter_, Tpetra::ADD);
  matrix_->fillComplete(matrix_->getDomainMap(), matrix_->getRangeMap());
}

}  // namespace contactlab
