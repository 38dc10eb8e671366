#include "core/problem/NodalAssembler.hpp"

#include "core/problem/MatrixAssembler.hpp"

namespace contactlab {
namespace {

// Overlap indices of the group's nodes that this rank owns.
std::vector<int> ownedNodes(const Mesh& mesh, const DofMap& dofs, const std::string& group) {
  std::vector<int> owned;
  for (auto node : mesh.boundaryNodes(group)) {
    const int n = dofs.overlapNodeIndex(node);
    if (n >= 0 && n < static_cast<int>(dofs.numOwnedNodes())) owned.push_back(n);
  }
  return owned;
}

}  // namespace

NodalAssembler::NodalAssembler(const SolidModel& model, const DofMap& dofs)
    : pointLoads_(model.pointLoads), numSprings_(model.springs.size()) {
  const Mesh& mesh = *model.mesh;
  const int dim = dofs.dim();
  for (int s = 0; s < static_cast<int>(model.springs.size()); ++s) {
    const NodalSpring& spring = model.springs[s];
    for (int n : ownedNodes(mesh, dofs, spring.group))
      for (int c : spring.components)
        springEntries_.push_back({s, n * dim + c, c, spring.stiffness});
  }
  for (int l = 0; l < static_cast<int>(pointLoads_.size()); ++l) {
    const PointLoad& load = pointLoads_[l];
    // Every rank knows the group's size: the share of each node is the same everywhere.
    const double nodes = static_cast<double>(mesh.boundaryNodes(load.group).size());
    const double share = load.distribution == PointLoad::Distribution::Total ? 1.0 / nodes : 1.0;
    for (int n : ownedNodes(mesh, dofs, load.group))
      for (int c = 0; c < dim; ++c)
        if (load.force[c] != 0.0)
          loadEntries_.push_back({l, n * dim + c, c, share * load.force[c]});
  }
}

void NodalAssembler::addSpringForces(const double* u, std::vector<double>& r) const {
  for (const auto& e : springEntries_)
    r[e.lid] += e.value * u[e.lid];
}

void NodalAssembler::addSpringStiffness(MatrixAssembler& assembler,
                                        const std::vector<char>& constrained) const {
  for (const auto& e : springEntries_)
    if (!constrained[e.lid]) assembler.addDiagonal(e.lid, e.value);
}

std::vector<std::array<double, 3>> NodalAssembler::localSpringForces(const double* u) const {
  std::vector<std::array<double, 3>> forces(numSprings_, {{0, 0, 0}});
  for (const auto& e : springEntries_)
    forces[e.term][e.component] -= e.value * u[e.lid];
  return forces;
}

void NodalAssembler::addPointLoads(double t, std::vector<double>& f) const {
  for (const auto& e : loadEntries_)
    f[e.lid] += e.value * pointLoads_[e.term].function(t);
}

}  // namespace contactlab
