#include "formulations/ContactAssembler.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <unordered_map>

namespace contactlab {

namespace {

// The column Map as Tpetra would make it: this rank's own ids in the monolithic Map's order,
// then the others grouped by owner, by id within an owner. Built here with the local rows
// (inserting global indices row by row cost 10 % of a generalized-Newton run on the hex27 tube,
// which builds a graph at most iterations). Collective (the owners are looked up).
class ColumnLayout {
 public:
  ColumnLayout(const Map& map, std::vector<GO> remote) : map_(map) {
    std::sort(remote.begin(), remote.end());
    remote.erase(std::unique(remote.begin(), remote.end()), remote.end());
    std::vector<int> owners(remote.size());
    map.getRemoteIndexList(Teuchos::ArrayView<const GO>(remote), Teuchos::ArrayView<int>(owners));
    std::vector<std::pair<int, GO>> byOwner(remote.size());
    for (std::size_t k = 0; k < remote.size(); ++k)
      byOwner[k] = {owners[k], remote[k]};
    std::sort(byOwner.begin(), byOwner.end());
    ids_.assign(map.getNodeElementList().begin(), map.getNodeElementList().end());
    for (const auto& [owner, gid] : byOwner) {
      remote_.emplace(gid, static_cast<LO>(ids_.size()));
      ids_.push_back(gid);
    }
  }
  const std::vector<GO>& ids() const { return ids_; }
  // The local column of gid; -1 when it is not a column here.
  LO operator()(GO gid) const {
    const LO lid = map_.getLocalElement(gid);
    if (lid != Teuchos::OrdinalTraits<LO>::invalid()) return lid;
    const auto it = remote_.find(gid);
    return it == remote_.end() ? LO(-1) : it->second;
  }

 private:
  const Map& map_;
  std::vector<GO> ids_;
  std::unordered_map<GO, LO> remote_;
};

}  // namespace

ContactAssembler::ContactAssembler(Teuchos::RCP<const Map> map, LO ownedDisplacements,
                                   const ContactSurfaceState& state, PartnerDofs partners)
    : map_(std::move(map)),
      ownedDisplacements_(ownedDisplacements),
      state_(state),
      partners_(std::move(partners)) {}

void ContactAssembler::buildGraph(const Matrix& solidTangent, std::vector<ContactPoint>& points) {
  const auto kLocal = solidTangent.getLocalMatrixHost();
  const auto kCols = solidTangent.getColMap();
  const LO owned = static_cast<LO>(map_->getNodeNumElements());
  const LO solidColumns = static_cast<LO>(kCols->getNodeNumElements());
  const LO invalid = Teuchos::OrdinalTraits<LO>::invalid();
  layOutRows(points);

  // Each point's columns (its dofs, geometryDofs and the partners of a dependent among them)
  // and the rows it adds them to (its own, and its dependents' partners', owned here).
  const auto couplings = [&](const ContactPoint& pt, std::vector<GO>& columns,
                             std::vector<LO>& rows) {
    columns.assign(pt.dofs.begin(), pt.dofs.end());
    columns.insert(columns.end(), pt.geometryDofs.begin(), pt.geometryDofs.end());
    rows.clear();
    for (std::size_t i = 0; i < pt.dofs.size(); ++i)
      if (pt.rows[i] >= 0) rows.push_back(pt.rows[i]);
    if (rows.empty() || !partners_) return;
    const std::size_t own = columns.size();
    for (std::size_t i = 0; i < own; ++i)
      for (const GO partner : partners_(columns[i])) {
        columns.push_back(partner);
        const LO row = map_->getLocalElement(partner);
        if (i < pt.dofs.size() && pt.rows[i] >= 0 && row != invalid) rows.push_back(row);
      }
  };
  std::vector<GO> columns;
  std::vector<LO> rows;

  std::vector<GO> remote;  // the columns this rank does not own
  for (LO c = 0; c < solidColumns; ++c)
    if (map_->getLocalElement(kCols->getGlobalElement(c)) == invalid)
      remote.push_back(kCols->getGlobalElement(c));
  for (const ContactPoint& pt : points) {
    couplings(pt, columns, rows);
    if (rows.empty()) continue;
    for (const GO gid : columns)
      if (map_->getLocalElement(gid) == invalid) remote.push_back(gid);
  }
  const ColumnLayout column(*map_, std::move(remote));
  const std::vector<GO>& columnIds = column.ids();

  // Each row's local columns, sorted: the solid's, then every point's on the rows it touches.
  std::vector<LO> solidColumn(solidColumns);
  for (LO c = 0; c < solidColumns; ++c)
    solidColumn[c] = column(kCols->getGlobalElement(c));
  std::vector<std::vector<LO>> added(owned);
  for (const ContactPoint& pt : points) {
    couplings(pt, columns, rows);
    for (const LO r : rows)
      for (const GO gid : columns)
        added[r].push_back(column(gid));
  }
  Teuchos::ArrayRCP<size_t> rowStart(owned + 1, 0);
  std::vector<LO> entries;
  entries.reserve(kLocal.graph.entries.extent(0));
  for (LO r = 0; r < owned; ++r) {
    const std::size_t first = entries.size();
    if (r < ownedDisplacements_)
      for (auto j = kLocal.graph.row_map(r); j < kLocal.graph.row_map(r + 1); ++j)
        entries.push_back(solidColumn[kLocal.graph.entries(j)]);
    entries.insert(entries.end(), added[r].begin(), added[r].end());
    const auto begin = entries.begin() + static_cast<std::ptrdiff_t>(first);
    if (!std::is_sorted(begin, entries.end())) std::sort(begin, entries.end());
    if (!added[r].empty()) entries.erase(std::unique(begin, entries.end()), entries.end());
    rowStart[r + 1] = entries.size();
  }

  // The same graph as the matrix's (a re-pairing that kept every coupling): keep the matrix,
  // and the direct solver its analysis. Decided together: the matrix is one object.
  int same = 0;
  if (!matrix_.is_null()) {
    const auto local = matrix_->getLocalMatrixHost();
    const auto ids = matrix_->getColMap()->getNodeElementList();
    same = local.graph.entries.extent(0) == entries.size() &&
           std::equal(ids.begin(), ids.end(), columnIds.begin(), columnIds.end()) &&
           std::equal(rowStart.begin(), rowStart.end(), local.graph.row_map.data()) &&
           std::equal(entries.begin(), entries.end(), local.graph.entries.data());
  }
  int allSame = 0;
  Teuchos::reduceAll(*map_->getComm(), Teuchos::REDUCE_MIN, same, Teuchos::outArg(allSame));
  if (!allSame) {
    auto columnMap = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                          Teuchos::ArrayView<const GO>(columnIds),
                                          map_->getIndexBase(), map_->getComm()));
    Teuchos::ArrayRCP<LO> columns(entries.size());
    std::copy(entries.begin(), entries.end(), columns.begin());
    auto graph = Teuchos::rcp(new Graph(map_, columnMap, rowStart, columns));
    graph->expertStaticFillComplete(map_, map_);
    matrix_ = Teuchos::rcp(new Matrix(graph));
    patternChanged_ = true;
  }

  // Where each solid entry sits in the new rows, by a scatter of each row's offsets by column
  // (a search per entry cost O(row length^2)).
  const auto local = matrix_->getLocalMatrixHost();
  std::vector<std::size_t> offsetOf(columnIds.size(), 0);
  solidOffsets_.assign(kLocal.graph.entries.extent(0), 0);
  for (LO r = 0; r < ownedDisplacements_; ++r) {
    for (auto k = local.graph.row_map(r); k < local.graph.row_map(r + 1); ++k)
      offsetOf[local.graph.entries(k)] = static_cast<std::size_t>(k);
    for (auto j = kLocal.graph.row_map(r); j < kLocal.graph.row_map(r + 1); ++j)
      solidOffsets_[j] = offsetOf[solidColumn[kLocal.graph.entries(j)]];
  }
  // A point with no row here has no column here either (-1, never used).
  const auto columnOf = [&column](GO gid) { return column(gid); };  // no copy of the layout
  for (ContactPoint& pt : points) {
    pt.cols.resize(pt.dofs.size());
    std::transform(pt.dofs.begin(), pt.dofs.end(), pt.cols.begin(), columnOf);
    pt.geometryCols.resize(pt.geometryDofs.size());
    std::transform(pt.geometryDofs.begin(), pt.geometryDofs.end(), pt.geometryCols.begin(),
                   columnOf);
  }
}

void ContactAssembler::layOutRows(std::vector<ContactPoint>& points) const {
  for (ContactPoint& pt : points) {
    pt.rows.assign(pt.dofs.size(), -1);
    for (std::size_t i = 0; i < pt.dofs.size(); ++i) {
      const LO row = map_->getLocalElement(pt.dofs[i]);
      if (row != Teuchos::OrdinalTraits<LO>::invalid()) pt.rows[i] = row;
    }
  }
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
