#include "formulations/ContactAssembler.hpp"

#include <algorithm>

namespace contactlab {

ContactAssembler::ContactAssembler(Teuchos::RCP<const Map> map, LO ownedDisplacements,
                                   const ContactSurfaceState& state)
    : map_(std::move(map)), ownedDisplacements_(ownedDisplacements), state_(state) {}

void ContactAssembler::buildGraph(const Matrix& solidTangent, std::vector<ContactPoint>& points) {
  const auto kLocal = solidTangent.getLocalMatrixHost();
  const auto kCols = solidTangent.getColMap();
  const std::size_t owned = map_->getNodeNumElements();
  const LO solidColumns = static_cast<LO>(kCols->getNodeNumElements());
  std::vector<GO> solidGlobal(solidColumns);
  for (LO c = 0; c < solidColumns; ++c)
    solidGlobal[c] = kCols->getGlobalElement(c);
  std::vector<std::vector<GO>> rows(owned);
  for (LO r = 0; r < ownedDisplacements_; ++r)
    for (auto j = kLocal.graph.row_map(r); j < kLocal.graph.row_map(r + 1); ++j)
      rows[r].push_back(solidGlobal[kLocal.graph.entries(j)]);
  std::vector<char> touched(owned, 0);  // rows that contact adds to (the others are unique)
  for (ContactPoint& pt : points) {
    pt.rows.assign(pt.dofs.size(), -1);
    for (std::size_t i = 0; i < pt.dofs.size(); ++i) {
      const LO row = map_->getLocalElement(pt.dofs[i]);
      if (row == Teuchos::OrdinalTraits<LO>::invalid()) continue;
      pt.rows[i] = row;
      touched[row] = 1;
      rows[row].insert(rows[row].end(), pt.dofs.begin(), pt.dofs.end());
      rows[row].insert(rows[row].end(), pt.geometryDofs.begin(), pt.geometryDofs.end());
    }
  }
  std::vector<size_t> lengths(owned);
  for (std::size_t r = 0; r < owned; ++r) {
    if (touched[r]) {
      std::sort(rows[r].begin(), rows[r].end());
      rows[r].erase(std::unique(rows[r].begin(), rows[r].end()), rows[r].end());
    }
    lengths[r] = rows[r].size();
  }
  auto graph = Teuchos::rcp(new Graph(map_, Teuchos::ArrayView<const size_t>(lengths)));
  for (std::size_t r = 0; r < owned; ++r)
    graph->insertGlobalIndices(map_->getGlobalElement(static_cast<LO>(r)),
                               Teuchos::ArrayView<const GO>(rows[r]));
  graph->fillComplete(map_, map_);
  matrix_ = Teuchos::rcp(new Matrix(graph));

  const auto local = matrix_->getLocalMatrixHost();
  const auto cols = matrix_->getColMap();
  // Where each solid entry sits in the new rows: the solid's local columns translated once,
  // each new row's offsets scattered by column (a search per entry cost O(row length^2): 30 %
  // of the graph's time on hex27, rows of ~375 entries).
  std::vector<LO> newColumn(solidColumns);
  for (LO c = 0; c < solidColumns; ++c)
    newColumn[c] = cols->getLocalElement(solidGlobal[c]);
  std::vector<std::size_t> offsetOf(cols->getNodeNumElements(), 0);
  solidOffsets_.assign(kLocal.graph.entries.extent(0), 0);
  for (LO r = 0; r < ownedDisplacements_; ++r) {
    for (auto k = local.graph.row_map(r); k < local.graph.row_map(r + 1); ++k)
      offsetOf[local.graph.entries(k)] = static_cast<std::size_t>(k);
    for (auto j = kLocal.graph.row_map(r); j < kLocal.graph.row_map(r + 1); ++j)
      solidOffsets_[j] = offsetOf[newColumn[kLocal.graph.entries(j)]];
  }
  for (ContactPoint& pt : points) {
    pt.cols.assign(pt.dofs.size(), -1);
    for (std::size_t i = 0; i < pt.dofs.size(); ++i)
      pt.cols[i] = cols->getLocalElement(pt.dofs[i]);
    pt.geometryCols.assign(pt.geometryDofs.size(), -1);
    for (std::size_t i = 0; i < pt.geometryDofs.size(); ++i)
      pt.geometryCols[i] = cols->getLocalElement(pt.geometryDofs[i]);
  }
  patternChanged_ = true;
}

bool ContactAssembler::takePatternChanged() {
  const bool changed = patternChanged_;
  patternChanged_ = false;
  return changed;
}

void ContactAssembler::begin(Vector* residual, const Vector* solidResidual,
                             const Matrix* solidTangent) {
  residual_ = Teuchos::null;
  if (residual) {
    residual->putScalar(0.0);
    residual_ = residual->getDataNonConst(0);
    auto src = solidResidual->getData(0);
    for (LO i = 0; i < ownedDisplacements_; ++i)
      residual_[i] = src[i];
  }
  withTangent_ = solidTangent != nullptr;
  if (!withTangent_) return;
  matrix_->resumeFill();
  matrix_->setAllToScalar(0.0);
  const auto local = matrix_->getLocalMatrixHost();
  double* values = local.values.data();
  const auto kValues = solidTangent->getLocalMatrixHost().values;
  for (std::size_t j = 0; j < solidOffsets_.size(); ++j)
    values[solidOffsets_[j]] += kValues(j);
}

void ContactAssembler::add(const ContactPoint& pt, const std::vector<double>& re,
                           const std::vector<double>& ke, bool geometric) {
  const int nd = static_cast<int>(pt.dofs.size());
  // Columns: the point's dofs, then (geometric linearization) the dofs around its facet.
  const int ng = geometric ? static_cast<int>(pt.geometryDofs.size()) : 0, nc = nd + ng;
  if (geometric) {
    columns_.assign(pt.cols.begin(), pt.cols.end());
    columns_.insert(columns_.end(), pt.geometryCols.begin(), pt.geometryCols.end());
  }
  const auto columnConstrained = [&](int j) {
    return state_.constrained(j < nd ? pt.surfacePos[j] : pt.geometrySurfacePos[j - nd]);
  };
  for (int i = 0; i < nd; ++i) {
    if (!contactForces_.is_null() && pt.rows[i] >= 0 && pt.rows[i] < ownedDisplacements_)
      contactForces_[pt.rows[i]] += re[i];
    if (pt.rows[i] < 0 || state_.constrained(pt.surfacePos[i])) continue;
    if (!residual_.is_null()) residual_[pt.rows[i]] += re[i];
    if (!withTangent_) continue;
    row_.assign(ke.begin() + static_cast<std::ptrdiff_t>(i) * nc,
                ke.begin() + static_cast<std::ptrdiff_t>(i + 1) * nc);
    for (int j = 0; j < nc; ++j)
      if (columnConstrained(j)) row_[j] = 0.0;
    matrix_->sumIntoLocalValues(pt.rows[i], nc, row_.data(),
                                geometric ? columns_.data() : pt.cols.data());
  }
}

void ContactAssembler::collectContactForces(Vector* forces) {
  contactForces_ = forces ? forces->getDataNonConst(0) : Teuchos::null;
}

void ContactAssembler::end() {
  if (withTangent_) matrix_->fillComplete(map_, map_);
  residual_ = Teuchos::null;
  contactForces_ = Teuchos::null;
}

}  // namespace contactlab
