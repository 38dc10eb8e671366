// Problem's outputs: the fields written per step, the material-state summary, errors against an
// exact solution and values at a mesh node. Read-only: none changes the converged state.
#include "base/GatherOnRoot.hpp"
#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/QuadratureRule.hpp"
#include "core/fem/ReferenceElement.hpp"
#include "core/problem/ElementKernel.hpp"
#include "core/problem/Problem.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace contactlab {

MaterialStateSummary Problem::materialState() const {
  std::array<double, 3> local{}, global{};  // max plastic strain, plastic volume, volume
  int plasticity = 0;
  std::vector<double> x, w;
  for (const auto& e : elements_) {
    if (e.stateOld.empty()) continue;
    plasticity = 1;
    const Material& material = *blockMaterial_[e.block];
    const ElementKernel& kernel = *kernels_[e.kernel];
    gatherCoordinates(e.nodes, x);
    w.resize(kernel.numQuadraturePoints());
    kernel.pointMeasures(x.data(), w.data());
    for (int q = 0; q < kernel.numQuadraturePoints(); ++q) {
      const double p = material.equivalentPlasticStrain(&e.stateOld[q * material.stateSize()]);
      local[0] = std::max(local[0], p);
      if (p > 0) local[1] += w[q];
      local[2] += w[q];
    }
  }
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, 1, local.data(), global.data());
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, 2, local.data() + 1, global.data() + 1);
  int anyPlasticity = 0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, plasticity, Teuchos::outArg(anyPlasticity));
  MaterialStateSummary summary;
  summary.plasticity = anyPlasticity > 0;
  summary.maxPlasticStrain = global[0];
  summary.plasticVolumeFraction = global[2] > 0 ? global[1] / global[2] : 0.0;
  return summary;
}

std::array<double, 6> Problem::elementStress(std::size_t index, const Vector& uOverlap,
                                             double t) const {
  const auto& e = elements_[index];
  auto uo = uOverlap.getData(0);
  std::vector<double> x, ue(e.rows.size());
  gatherCoordinates(e.nodes, x);
  for (std::size_t i = 0; i < e.rows.size(); ++i)
    ue[i] = uo[e.rows[i]];
  // Evaluated from the converged state into a scratch trial state: output changes nothing.
  std::vector<double> scratch(e.stateNew.size());
  std::array<double, 6> average{};
  kernels_[e.kernel]->stresses(x.data(), ue.data(), *blockMaterial_[e.block],
                               e.stateOld.empty() ? nullptr : e.stateOld.data(),
                               scratch.empty() ? nullptr : scratch.data(), nullptr, average.data(),
                               blockTemperature(e.block, t));
  return average;
}

double Problem::elementPlasticStrain(const LocalElement& e) const {
  if (e.stateOld.empty()) return 0.0;
  const Material& law = *blockMaterial_[e.block];
  const int nq = static_cast<int>(e.stateOld.size()) / law.stateSize();
  double sum = 0;
  for (int q = 0; q < nq; ++q)
    sum += law.equivalentPlasticStrain(&e.stateOld[q * law.stateSize()]);
  return sum / nq;
}

NodalFields Problem::nodalFields(const Vector& u, double t) const {
  // Per node: the sums of its elements' stresses (and plastic strains) and their count, on the
  // overlap map's rows of component 0, added into the owned rows, then gathered on rank 0.
  const int d = dim();
  const bool plasticity = model_.hasInternalVariables();
  const int width = plasticity ? 8 : 7;
  MultiVector overlap(dofs_->overlapMap(), width), owned(dofs_->ownedMap(), width);
  auto uOverlap = overlapCopy(u);
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    const auto s = elementStress(i, *uOverlap, t);
    const double plastic = plasticity ? elementPlasticStrain(elements_[i]) : 0.0;
    for (int a : elements_[i].nodes) {
      const LO row = static_cast<LO>(a * d);
      for (int k = 0; k < 6; ++k)
        overlap.sumIntoLocalValue(row, k, s[k]);
      if (plasticity) overlap.sumIntoLocalValue(row, 6, plastic);
      overlap.sumIntoLocalValue(row, width - 1, 1.0);
    }
  }
  owned.doExport(overlap, *importer_, Tpetra::ADD);
  const std::size_t ownedNodes = dofs_->numOwnedNodes();
  std::vector<std::int64_t> nodes(dofs_->overlapNodes().begin(),
                                  dofs_->overlapNodes().begin() + ownedNodes);
  std::vector<double> values(ownedNodes * width);
  for (int k = 0; k < width; ++k) {
    auto column = owned.getData(k);
    for (std::size_t a = 0; a < ownedNodes; ++a)
      values[a * width + k] = column[a * d];
  }
  const MPI_Comm comm = rawMpiComm(comm_);
  const std::vector<std::int64_t> allNodes = gatherOnRoot(nodes, MPI_INT64_T, comm);
  const std::vector<double> allValues = gatherOnRoot(values, MPI_DOUBLE, comm);
  NodalFields fields;
  if (comm_->getRank() != 0) return fields;
  const std::size_t n = model_.mesh->numNodes();
  const double nan = std::nan("");
  fields.stress.assign(6 * n, nan);
  fields.vonMises.assign(n, nan);
  if (plasticity) fields.plasticStrain.assign(n, nan);
  for (std::size_t i = 0; i < allNodes.size(); ++i) {
    const double* v = &allValues[i * width];
    const double count = v[width - 1];
    if (count == 0) continue;
    std::array<double, 6> s;
    for (int k = 0; k < 6; ++k)
      fields.stress[6 * allNodes[i] + k] = s[k] = v[k] / count;
    fields.vonMises[allNodes[i]] = vonMisesStress(s);
    if (plasticity) fields.plasticStrain[allNodes[i]] = v[6] / count;
  }
  return fields;
}

MeshPiece Problem::outputPiece(const Vector& u, double t) const {
  const Mesh& mesh = *model_.mesh;
  const int dim = this->dim();
  auto uOverlap = overlapCopy(u);
  auto uo = uOverlap->getData(0);
  MeshPiece piece;
  const auto& nodes = dofs_->overlapNodes();
  piece.points.reserve(3 * nodes.size());
  FieldData disp{"displacement", 3, std::vector<double>(3 * nodes.size(), 0.0)};
  for (std::size_t a = 0; a < nodes.size(); ++a) {
    for (int i = 0; i < 3; ++i)
      piece.points.push_back(mesh.coords[3 * nodes[a] + i]);
    for (int c = 0; c < dim; ++c)
      disp.values[3 * a + c] = uo[a * dim + c];
  }
  piece.pointData.push_back(std::move(disp));
  FieldData stress{"stress", 6, {}}, vm{"von_mises", 1, {}}, material{"material", 1, {}},
      rank{"rank", 1, {}};
  std::vector<double> plasticStrain(elements_.size(), 0.0), plastic(elements_.size(), 0.0);
  piece.offsets.push_back(0);
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    const auto& e = elements_[i];
    piece.cellTypes.push_back(mesh.blocks[e.block].type);
    piece.connectivity.insert(piece.connectivity.end(), e.nodes.begin(), e.nodes.end());
    piece.offsets.push_back(static_cast<std::int64_t>(piece.connectivity.size()));
    const auto s = elementStress(i, *uOverlap, t);
    stress.values.insert(stress.values.end(), s.begin(), s.end());
    vm.values.push_back(vonMisesStress(s));
    material.values.push_back(e.block);
    rank.values.push_back(comm_->getRank());
    plasticStrain[i] = elementPlasticStrain(e);
    plastic[i] = e.plastic ? 1.0 : 0.0;
  }
  piece.cellData = {std::move(stress), std::move(vm), std::move(material), std::move(rank)};
  // Every rank writes the same fields (a piece without plastic elements writes zeros).
  if (model_.hasInternalVariables()) {
    piece.cellData.push_back({"equivalent_plastic_strain", 1, std::move(plasticStrain)});
    piece.cellData.push_back({"plastic", 1, std::move(plastic)});
  }
  // With prescribed temperatures, each cell's (its block's at t; a block without one is at its
  // material's reference temperature). Only then: a model without them writes what it wrote.
  if (!model_.temperatures.empty()) {
    FieldData temperature{"temperature", 1, {}};
    for (const auto& e : elements_)
      temperature.values.push_back(
          blockTemperature(e.block, t)
              .value_or(blockMaterial_[e.block]->referenceTemperature().value_or(0.0)));
    piece.cellData.push_back(std::move(temperature));
  }
  return piece;
}

DisplacementErrors Problem::displacementErrors(
    const Vector& u, const std::function<void(const double* x, double* u)>& exact,
    const std::function<void(const double* x, double* grad)>& exactGradient) const {
  const Mesh& mesh = *model_.mesh;
  const int dim = this->dim();
  auto uOverlap = overlapCopy(u);
  auto uo = uOverlap->getData(0);
  std::array<double, 4> local{}, global{};  // l2^2, energy^2, l2Exact^2, energyExact^2
  std::vector<double> x, N, dN, dNdx;
  for (const auto& e : elements_) {
    const auto& block = mesh.blocks[e.block];
    const auto& ref = ReferenceElement::get(block.type);
    const auto& rule = quadratureRule(block.type, 2 * info(block.type).order + 2);
    const int n = static_cast<int>(e.nodes.size());
    gatherCoordinates(e.nodes, x);
    N.resize(n);
    dN.resize(n * dim);
    dNdx.resize(n * dim);
    for (int q = 0; q < rule.size(); ++q) {
      const double* xi = &rule.points[q * rule.dim];
      ref.shape(xi, N.data());
      ref.shapeDerivatives(xi, dN.data());
      const double w =
          rule.weights[q] * physicalGradients(dim, n, x.data(), dN.data(), dNdx.data());
      double point[3] = {0, 0, 0}, uh[3] = {0, 0, 0}, gh[9] = {0}, ue[3] = {0, 0, 0}, ge[9] = {0};
      interpolatePosition(n, x.data(), N.data(), point);
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < dim; ++i) {
          const double value = uo[e.rows[a * dim + i]];
          uh[i] += N[a] * value;
          for (int j = 0; j < dim; ++j)
            gh[i * 3 + j] += dNdx[a * dim + j] * value;
        }
      exact(point, ue);
      exactGradient(point, ge);
      for (int i = 0; i < dim; ++i) {
        local[0] += w * (uh[i] - ue[i]) * (uh[i] - ue[i]);
        local[2] += w * ue[i] * ue[i];
        for (int j = 0; j < dim; ++j) {
          local[1] += w * (gh[i * 3 + j] - ge[i * 3 + j]) * (gh[i * 3 + j] - ge[i * 3 + j]);
          local[3] += w * ge[i * 3 + j] * ge[i * 3 + j];
        }
      }
    }
  }
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, 4, local.data(), global.data());
  return {std::sqrt(global[0]), std::sqrt(global[1]), std::sqrt(global[2]), std::sqrt(global[3])};
}

std::array<double, 3> Problem::nodeDisplacement(const Vector& u, std::int64_t meshNode) const {
  std::array<double, 3> local{}, global{};
  if (dofs_->nodeOwner(meshNode) == comm_->getRank()) {
    auto data = u.getData(0);
    const int n = dofs_->overlapNodeIndex(meshNode);
    for (int c = 0; c < dim(); ++c)
      local[c] = data[n * dim() + c];
  }
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, 3, local.data(), global.data());
  return global;
}

std::array<double, 6> Problem::nodeStress(const Vector& u, std::int64_t meshNode, double t) const {
  return nodeStresses(u, {meshNode}, t)[0];
}

std::vector<std::array<double, 6>> Problem::nodeStresses(const Vector& u,
                                                         const std::vector<std::int64_t>& meshNodes,
                                                         double t) const {
  // Average over the elements around each node, whichever rank assembles them: one overlap
  // import and one pass over the elements for all the nodes, each element's stress evaluated
  // once however many of the nodes it holds.
  auto uOverlap = overlapCopy(u);
  const std::size_t count = meshNodes.size();
  std::vector<double> local(7 * count, 0.0), global(7 * count, 0.0);
  std::vector<int> overlap(count);
  for (std::size_t j = 0; j < count; ++j)
    overlap[j] = dofs_->overlapNodeIndex(meshNodes[j]);
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    const auto& e = elements_[i];
    std::optional<std::array<double, 6>> s;
    for (std::size_t j = 0; j < count; ++j) {
      if (overlap[j] < 0 || std::find(e.nodes.begin(), e.nodes.end(), overlap[j]) == e.nodes.end())
        continue;
      if (!s) s = elementStress(i, *uOverlap, t);
      for (int k = 0; k < 6; ++k)
        local[7 * j + k] += (*s)[k];
      local[7 * j + 6] += 1.0;
    }
  }
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(7 * count), local.data(),
                     global.data());
  std::vector<std::array<double, 6>> stresses(count);
  for (std::size_t j = 0; j < count; ++j)
    for (int k = 0; k < 6; ++k)
      stresses[j][k] = global[7 * j + 6] > 0 ? global[7 * j + k] / global[7 * j + 6] : 0.0;
  return stresses;
}

}  // namespace contactlab
