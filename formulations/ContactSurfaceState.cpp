#include "formulations/ContactSurfaceState.hpp"

namespace contactlab {

ContactSurfaceState::ContactSurfaceState(const Mesh& mesh, const DofMap& dofs,
                                         Teuchos::RCP<const Map> map, LO ownedDisplacements,
                                         const std::set<std::int64_t>& nodes, GO numMultipliers,
                                         const std::vector<char>& constrained)
    : mesh_(mesh), dim_(dofs.dim()), firstMultiplier_(dofs.numGlobalDofs()) {
  index_.assign(mesh.numNodes(), -1);
  std::vector<GO> gids;
  int k = 0;
  for (std::int64_t node : nodes) {
    index_[node] = k++;
    for (int c = 0; c < dim_; ++c)
      gids.push_back(dofs.globalNode(node) * dim_ + c);
  }
  displacementDofs_ = gids.size();
  for (GO m = 0; m < numMultipliers; ++m)
    gids.push_back(firstMultiplier_ + m);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto surfaceMap =
      Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(gids), 0, dofs.comm()));
  importer_ = Teuchos::rcp(new Import(map, surfaceMap));
  replicated_ = Teuchos::rcp(new Vector(surfaceMap));
  converged_.assign(displacementDofs_, 0.0);

  // Dirichlet flags of the surface dofs, from their owners.
  Vector flags(map);
  {
    auto f = flags.getDataNonConst(0);
    for (LO i = 0; i < ownedDisplacements; ++i)
      f[i] = constrained[i] ? 1.0 : 0.0;
  }
  Vector surfaceFlags(surfaceMap);
  surfaceFlags.doImport(flags, *importer_, Tpetra::INSERT);
  auto sf = surfaceFlags.getData(0);
  constrained_.assign(sf.size(), 0);
  for (std::size_t i = 0; i < displacementDofs_; ++i)
    constrained_[i] = sf[i] > 0.5;
}

void ContactSurfaceState::import(const Vector& x) {
  replicated_->doImport(x, *importer_, Tpetra::INSERT);
}

void ContactSurfaceState::commit() {
  auto s = replicated_->getData(0);
  for (std::size_t i = 0; i < displacementDofs_; ++i)
    converged_[i] = s[i];
}

std::array<double, 3> ContactSurfaceState::displacement(std::int64_t node, bool converged) const {
  const int k = index_[node];
  std::array<double, 3> u{};
  if (converged) {
    for (int c = 0; c < dim_; ++c)
      u[c] = converged_[k * dim_ + c];
  } else {
    auto s = replicated_->getData(0);
    for (int c = 0; c < dim_; ++c)
      u[c] = s[k * dim_ + c];
  }
  return u;
}

std::array<double, 3> ContactSurfaceState::position(std::int64_t node) const {
  auto u = displacement(node, false);
  for (int i = 0; i < 3; ++i)
    u[i] += mesh_.coords[3 * node + i];
  return u;
}

}  // namespace contactlab
