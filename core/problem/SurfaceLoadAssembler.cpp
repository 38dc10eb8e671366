#include "core/problem/SurfaceLoadAssembler.hpp"

#include "base/InputError.hpp"
#include "core/problem/MatrixAssembler.hpp"
#include "core/problem/SurfaceLoadKernel.hpp"

#include <algorithm>
#include <array>
#include <iterator>
#include <set>

namespace contactlab {

SurfaceLoadAssembler::SurfaceLoadAssembler(const SolidModel& model, const DofMap& dofs,
                                           const std::vector<int>& partition)
    : dim_(dofs.dim()), axisymmetric_(model.axisymmetric), loads_(model.surfaceLoads) {
  if (loads_.empty()) return;
  locate(model, dofs, partition);
  for (const auto& facet : facets_)
    if (!kernels_.count(facet.type))
      kernels_[facet.type] =
          std::make_unique<SurfaceLoadKernel>(facet.type, dim_, -1, axisymmetric_);
}

SurfaceLoadAssembler::~SurfaceLoadAssembler() = default;

void SurfaceLoadAssembler::locate(const SolidModel& model, const DofMap& dofs,
                                  const std::vector<int>& partition) {
  const Mesh& mesh = *model.mesh;
  const int rank = dofs.comm()->getRank();
  std::vector<std::vector<int>> elementsOfNode(mesh.numNodes());
  const auto refs = allElements(mesh);
  std::set<std::int64_t> loadedNodes;
  for (const auto& load : loads_)
    for (auto n : mesh.boundaryNodes(load.group))
      loadedNodes.insert(n);
  std::vector<int> localIndex(refs.size(), -1);  // element's index among this rank's
  int local = 0;
  for (std::size_t e = 0; e < refs.size(); ++e) {
    if (partition[e] == rank) localIndex[e] = local++;
    const auto& block = mesh.blocks[refs[e].block];
    const int npc = block.nodesPerCell();
    for (int a = 0; a < npc; ++a) {
      const auto n = block.nodes[refs[e].cell * npc + a];
      if (loadedNodes.count(n)) elementsOfNode[n].push_back(static_cast<int>(e));
    }
  }
  std::vector<char> follows(loads_.size(), 0);
  for (int l = 0; l < static_cast<int>(loads_.size()); ++l) {
    const SurfaceLoad& load = loads_[l];
    const bool pressure = load.kind == SurfaceLoad::Kind::Pressure && !load.field;
    for (const auto* g : mesh.findBoundaries(load.group)) {
      const int npc = g->nodesPerCell();
      for (std::size_t f = 0; f < g->size(); ++f) {
        const std::int64_t* nodes = &g->nodes[f * npc];
        std::vector<int> candidates = elementsOfNode[nodes[0]];
        for (int a = 1; a < npc && !candidates.empty(); ++a) {
          const auto& other = elementsOfNode[nodes[a]];
          std::vector<int> common;
          std::set_intersection(candidates.begin(), candidates.end(), other.begin(), other.end(),
                                std::back_inserter(common));
          candidates.swap(common);
        }
        if (candidates.empty())
          throw InputError("facet " + std::to_string(g->tags[f]) + " of group '" + g->name +
                           "' belongs to no element of the mesh " + mesh.source);
        const int parent = candidates.front();
        const auto& block = mesh.blocks[refs[parent].block];
        const bool finiteStrain =
            model.materials.at(block.name)->kinematics() == Kinematics::FiniteStrain;
        if (pressure && load.follower == SurfaceLoad::Follower::Yes && !finiteStrain)
          throw InputError(
              "load '" + load.name + "' asks for a follower pressure (Follower: true), but facet " +
              std::to_string(g->tags[f]) + " of group '" + g->name + "' belongs to block '" +
              block.name + "', whose material '" + model.materials.at(block.name)->name() +
              "' is small-strain: a small-strain body has no current "
              "configuration for the pressure to follow; use Follower: automatic "
              "or false, or a finite-strain material");
        const bool follower =
            pressure && finiteStrain && load.follower != SurfaceLoad::Follower::No;
        if (follower) follows[l] = 1;
        if (partition[parent] != rank) continue;
        Facet facet{l, g->type, follower, {}, {}, -1, {}};
        for (int a = 0; a < npc; ++a) {
          facet.overlapNodes.push_back(dofs.overlapNodeIndex(nodes[a]));
          for (int i = 0; i < 3; ++i)
            facet.x.push_back(mesh.coords[3 * nodes[a] + i]);
        }
        if (follower) {
          facet.element = localIndex[parent];
          const std::int64_t* cell = &block.nodes[refs[parent].cell * block.nodesPerCell()];
          for (int a = 0; a < npc; ++a)
            facet.elementNodes.push_back(
                static_cast<int>(std::find(cell, cell + block.nodesPerCell(), nodes[a]) - cell));
          followerFacets_.push_back(facets_.size());
        }
        facets_.push_back(std::move(facet));
      }
    }
  }
  for (std::size_t l = 0; l < loads_.size(); ++l)
    if (follows[l]) followerLoads_.push_back(loads_[l].name);
}

void SurfaceLoadAssembler::gather(const Facet& facet, const double* u,
                                  std::vector<double>& ue) const {
  ue.resize(facet.overlapNodes.size() * dim_);
  for (std::size_t a = 0; a < facet.overlapNodes.size(); ++a)
    for (int c = 0; c < dim_; ++c)
      ue[a * dim_ + c] = u[facet.overlapNodes[a] * dim_ + c];
}

void SurfaceLoadAssembler::addForces(double t, const double* u, std::vector<double>& f) const {
  const int dim = dim_;
  std::vector<double> fe, ue;
  for (const auto& facet : facets_) {
    const auto& load = loads_[facet.load];
    const double* x = facet.x.data();
    fe.assign(facet.overlapNodes.size() * dim, 0.0);
    const double scale = load.function(t);
    const SurfaceLoadKernel& kernel = *kernels_.at(facet.type);
    if (load.field) {
      kernel.traction(
          x, [&](const double* p, double* tr) { load.field(p, t, tr); }, fe.data());
    } else if (facet.follower) {
      gather(facet, u, ue);
      kernel.followerPressure(x, ue.data(), load.pressure * scale, fe.data(), nullptr);
    } else if (load.kind == SurfaceLoad::Kind::Pressure) {
      kernel.pressure(x, load.pressure * scale, fe.data());
    } else {
      std::array<double, 3> tr{};
      for (int i = 0; i < 3; ++i)
        tr[i] = load.traction[i] * scale;
      kernel.traction(
          x,
          [&](const double*, double* out) {
            for (int i = 0; i < 3; ++i)
              out[i] = tr[i];
          },
          fe.data());
    }
    for (std::size_t a = 0; a < facet.overlapNodes.size(); ++a)
      for (int c = 0; c < dim; ++c)
        f[facet.overlapNodes[a] * dim + c] += fe[a * dim + c];
  }
}

void SurfaceLoadAssembler::addStiffness(double t, const double* u, MatrixAssembler& assembler,
                                        const std::vector<char>& constrained) const {
  std::vector<double> ue, fe, dfdu;
  for (std::size_t index : followerFacets_) {
    const Facet& facet = facets_[index];
    const auto& load = loads_[facet.load];
    const SurfaceLoadKernel& kernel = *kernels_.at(facet.type);
    const int nd = kernel.numDofs();
    gather(facet, u, ue);
    fe.resize(nd);
    dfdu.resize(static_cast<std::size_t>(nd) * nd);
    kernel.followerPressure(facet.x.data(), ue.data(), load.pressure * load.function(t), fe.data(),
                            dfdu.data());
    // R = f_int - f_ext: the tangent takes -df_ext/du.
    for (double& v : dfdu)
      v = -v;
    assembler.add(static_cast<std::size_t>(facet.element), facet.elementNodes, dfdu.data(),
                  constrained);
  }
}

}  // namespace contactlab
