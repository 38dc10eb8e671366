#include "core/problem/Problem.hpp"

#include "base/InputError.hpp"
#include "core/fem/IsoparametricMap.hpp"
#include "core/fem/QuadratureRule.hpp"
#include "core/fem/ReferenceElement.hpp"
#include "core/materials/PlaneStress.hpp"
#include "core/problem/AxisymmetricModel.hpp"
#include "core/problem/CollectiveError.hpp"
#include "core/problem/ElementKernel.hpp"
#include "core/problem/ElementTechnology.hpp"
#include "core/problem/ElementUpdateError.hpp"
#include "core/problem/LinearConstraints.hpp"
#include "core/problem/MassKernel.hpp"
#include "core/problem/MatrixAssembler.hpp"
#include "core/problem/NodalAssembler.hpp"
#include "core/problem/PlaneStressModel.hpp"
#include "core/problem/SurfaceLoadAssembler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <tuple>

namespace contactlab {

namespace {

// f = K u of a linear element (Problem.hpp), K row major. K annihilates the element's
// translations (axisymmetric: the axial one only; a radial translation strains the hoop), so
// they are taken out of u first (into `deformation`): the round-off of the product then scales
// with the element's deformation, not with how far it moved (with the whole of u, the mortar 3D
// patch tests' Lagrange runs stalled at a residual above their target).
void linearElementForce(const std::vector<double>& K, const std::vector<double>& u, int dim,
                        bool axisymmetric, std::vector<double>& deformation,
                        std::vector<double>& f) {
  const std::size_t n = u.size(), nodes = n / dim;
  const int first = axisymmetric ? 1 : 0;
  double mean[3] = {0, 0, 0};
  for (std::size_t a = 0; a < nodes; ++a)
    for (int c = first; c < dim; ++c)
      mean[c] += u[a * dim + c] / static_cast<double>(nodes);
  deformation.resize(n);
  for (std::size_t a = 0; a < nodes; ++a)
    for (int c = 0; c < dim; ++c)
      deformation[a * dim + c] = u[a * dim + c] - mean[c];
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0;
    for (std::size_t j = 0; j < n; ++j)
      sum += K[i * n + j] * deformation[j];
    f[i] = sum;
  }
}

std::string elementLabel(const Mesh& mesh, int block, std::size_t cell) {
  const auto& b = mesh.blocks[block];
  return "element " + std::to_string(cell) + " (gmsh tag " + std::to_string(b.tags[cell]) +
         ") of block '" + b.name + "' in " + mesh.source;
}

}  // namespace

void Problem::gatherCoordinates(const std::vector<int>& overlapNodes,
                                std::vector<double>& x) const {
  const Mesh& mesh = *model_.mesh;
  x.resize(3 * overlapNodes.size());
  for (std::size_t a = 0; a < overlapNodes.size(); ++a)
    for (int i = 0; i < 3; ++i)
      x[3 * a + i] = mesh.coords[3 * dofs_->overlapNodes()[overlapNodes[a]] + i];
}

Problem::Problem(SolidModel model, const Teuchos::RCP<const Comm>& comm)
    : model_(std::move(model)), comm_(comm) {
  const Mesh& mesh = *model_.mesh;
  checkModel();
  resolveSymmetryConditions(model_);
  const auto partition = partitionElements(mesh, rawMpiComm(comm));
  const std::vector<TieEquation> ties = tieEquations(model_);
  dofs_ = std::make_unique<DofMap>(mesh, partition, comm, linkedNodes(ties));

  blockMaterial_.resize(mesh.blocks.size());
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const auto& law = model_.materials.at(mesh.blocks[b].name);
    if (model_.planeStress) {
      planeStressLaws_.push_back(std::make_shared<PlaneStress>(law));
      blockMaterial_[b] = planeStressLaws_.back().get();
    } else {
      blockMaterial_[b] = law.get();
    }
  }
  blockTemperature_.assign(mesh.blocks.size(), nullptr);
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b)
    for (const auto& temperature : model_.temperatures)
      if (temperature.block == mesh.blocks[b].name) blockTemperature_[b] = &temperature;

  // Every rank resolves every block's technology, so that a refusal is the same everywhere.
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const auto& block = mesh.blocks[b];
    const auto requested = model_.elementTechnologies.find(block.name);
    blockTechnology_.push_back(resolveBlockTechnology(
        block.name, requested == model_.elementTechnologies.end() ? "automatic" : requested->second,
        *blockMaterial_[b], elementSetting(static_cast<int>(b))));
  }

  std::map<std::tuple<ElementType, Kinematics, std::string>, int> kernelOf;
  const int dim = mesh.dim;
  for (const auto& ref : dofs_->localElements()) {
    const auto& block = mesh.blocks[ref.block];
    const Kinematics kinematics = blockMaterial_[ref.block]->kinematics();
    const BlockTechnology& technology = blockTechnology_[ref.block];
    auto [it, inserted] = kernelOf.emplace(std::make_tuple(block.type, kinematics, technology.name),
                                           static_cast<int>(kernels_.size()));
    if (inserted) {
      kernels_.push_back(technology.technology->kernel(elementSetting(ref.block)));
      massKernels_.push_back(std::make_unique<MassKernel>(block.type, model_.axisymmetric));
    }
    LocalElement e;
    e.block = ref.block;
    e.cell = ref.cell;
    e.kernel = it->second;
    const int npc = block.nodesPerCell();
    for (int a = 0; a < npc; ++a) {
      const int n = dofs_->overlapNodeIndex(block.nodes[ref.cell * npc + a]);
      e.nodes.push_back(n);
      for (int c = 0; c < dim; ++c)
        e.rows.push_back(n * dim + c);
    }
    e.linear = kinematics == Kinematics::SmallStrain && blockMaterial_[ref.block]->linear() &&
               blockMaterial_[ref.block]->stateSize() == 0 &&
               blockTemperature_[ref.block] == nullptr;
    const int stateSize = blockMaterial_[ref.block]->stateSize();
    if (stateSize > 0) {
      const int nq = kernels_[e.kernel]->numQuadraturePoints();
      e.stateOld.resize(static_cast<std::size_t>(nq) * stateSize);
      kernels_[e.kernel]->initializeState(*blockMaterial_[ref.block], e.stateOld.data());
      e.stateNew = e.stateOld;
    }
    elements_.push_back(std::move(e));
  }
  allLinear_ = std::all_of(elements_.begin(), elements_.end(),
                           [](const LocalElement& e) { return e.linear; });

  // Inverted or degenerate elements are input errors: find them before anything runs.
  collectively(*comm, [&] { checkElementGeometry(); });

  // Constrained dofs.
  const auto& overlap = dofs_->overlapNodes();
  constrained_.assign(overlap.size() * dim, 0);
  for (int d = 0; d < static_cast<int>(model_.dirichlet.size()); ++d) {
    const auto& bc = model_.dirichlet[d];
    for (auto node : mesh.boundaryNodes(bc.group)) {
      const int n = dofs_->overlapNodeIndex(node);
      if (n < 0) continue;
      for (int c : bc.components) {
        constrained_[n * dim + c] = 1;
        if (n < static_cast<int>(dofs_->numOwnedNodes()))
          constraints_.push_back({n * dim + c, d, c, node});
      }
    }
  }
  linearConstraints_ = std::make_unique<LinearConstraints>(model_, *dofs_, ties);
  for (const auto& bc : model_.dirichlet)
    reactions_.push_back({bc.name, {}});
  for (const auto& s : model_.symmetries)
    reactions_.push_back({s.name, {}});
  for (const auto& tie : model_.ties)
    reactions_.push_back({tie.name, {}});
  for (const auto& spring : model_.springs)
    springForces_.push_back({spring.name, {}});

  for (const auto& load : model_.centrifugalLoads) {
    try {
      centrifugal_.emplace_back(load, dim, model_.axisymmetric);
    } catch (const std::invalid_argument& e) {
      throw InputError(e.what());
    }
  }
  collectively(*comm, [&] {
    surfaceLoads_ = std::make_unique<SurfaceLoadAssembler>(model_, *dofs_, partition);
  });
  nodal_ = std::make_unique<NodalAssembler>(model_, *dofs_);
  buildGraph();
}

ElementSetting Problem::elementSetting(int block) const {
  ElementSetting setting;
  setting.type = model_.mesh->blocks[block].type;
  setting.kinematics = blockMaterial_[block]->kinematics();
  setting.axisymmetric = model_.axisymmetric;
  setting.planeStress = model_.planeStress;
  return setting;
}

bool Problem::tangentSymmetric() const {
  if (!followerLoads().empty()) return false;
  for (std::size_t b = 0; b < blockTechnology_.size(); ++b)
    if (!blockMaterial_[b]->symmetricTangent() || !blockTechnology_[b].technology->keepsSymmetry())
      return false;
  return true;
}

void Problem::checkElementGeometry() const {
  const Mesh& mesh = *model_.mesh;
  const int dim = mesh.dim;
  std::vector<double> x, dN, dNdx;
  for (const auto& e : elements_) {
    const auto& block = mesh.blocks[e.block];
    const auto& ref = ReferenceElement::get(block.type);
    const auto& rule = quadratureRule(block.type, stiffnessQuadratureDegree(block.type));
    gatherCoordinates(e.nodes, x);
    dN.resize(e.nodes.size() * dim);
    dNdx.resize(e.nodes.size() * dim);
    try {
      for (int q = 0; q < rule.size(); ++q) {
        ref.shapeDerivatives(&rule.points[q * rule.dim], dN.data());
        physicalGradients(dim, static_cast<int>(e.nodes.size()), x.data(), dN.data(), dNdx.data());
      }
    } catch (const InvalidElementError& err) {
      throw InputError(err.withLabel(elementLabel(mesh, e.block, e.cell)).what());
    }
  }
}

Problem::~Problem() = default;

void checkBlockMaterials(const SolidModel& model) {
  const Mesh& mesh = *model.mesh;
  const std::string where = "mesh " + mesh.source;
  // A material under a name no block has first: the likely slip, and the block it was meant for
  // then has none.
  for (const auto& [name, material] : model.materials)
    if (mesh.findBlocks(name).empty()) {
      std::string blocks;
      for (const auto& b : mesh.blockNames())
        blocks += (blocks.empty() ? "" : ", ") + b;
      throw InputError("material given for block '" + name + "', which is not in " + where +
                       "; its blocks are: " + blocks);
    }
  for (const auto& name : mesh.blockNames())
    if (!model.materials.count(name))
      throw InputError("block '" + name + "' of " + where + " has no material");
}

void Problem::checkModel() const {
  const Mesh& mesh = *model_.mesh;
  const std::string where = "mesh " + mesh.source;
  checkBlockMaterials(model_);
  auto checkGroup = [&](const std::string& kind, const std::string& name,
                        const std::string& group) {
    try {
      mesh.boundaryNodes(group);
    } catch (const std::invalid_argument& e) {
      throw InputError(kind + " '" + name + "': " + e.what());
    }
  };
  auto checkComponents = [&](const std::string& kind, const std::string& name,
                             const std::vector<int>& components) {
    for (int c : components)
      if (c < 0 || c >= mesh.dim)
        throw InputError(kind + " '" + name + "' acts on component " + std::to_string(c) +
                         " of a " + std::to_string(mesh.dim) + "D model");
  };
  for (const auto& bc : model_.dirichlet) {
    checkGroup("Dirichlet condition", bc.name, bc.group);
    checkComponents("Dirichlet condition", bc.name, bc.components);
  }
  for (const auto& spring : model_.springs) {
    checkGroup("spring", spring.name, spring.group);
    checkComponents("spring", spring.name, spring.components);
    if (!(spring.stiffness > 0) || !std::isfinite(spring.stiffness))
      throw InputError("spring '" + spring.name + "' has stiffness " +
                       std::to_string(spring.stiffness) + ": it must be a finite number > 0");
  }
  for (const auto& load : model_.pointLoads)
    checkGroup("point load", load.name, load.group);
  for (const auto& load : model_.surfaceLoads) {
    checkGroup("load", load.name, load.group);
    for (const auto* g : mesh.findBoundaries(load.group))
      if (g->dim != mesh.dim - 1)
        throw InputError("load '" + load.name + "' acts on group '" + load.group +
                         "', which is not made of facets (dimension " + std::to_string(g->dim) +
                         ")");
  }
  for (const auto& body : model_.bodyForces)
    if (!body.block.empty() && mesh.findBlocks(body.block).empty())
      throw InputError("body force '" + body.name + "' names block '" + body.block +
                       "', which is not in " + where);
  for (const auto& load : model_.centrifugalLoads)
    if (!load.block.empty() && mesh.findBlocks(load.block).empty())
      throw InputError("centrifugal load '" + load.name + "' names block '" + load.block +
                       "', which is not in " + where);
  std::set<std::string> heated;
  for (const auto& temperature : model_.temperatures) {
    const auto material = model_.materials.find(temperature.block);
    if (material == model_.materials.end())
      throw InputError("temperature given for block '" + temperature.block +
                       "', which has no material");
    if (!material->second->referenceTemperature())
      throw InputError("temperature given for block '" + temperature.block + "', whose material " +
                       material->second->name() +
                       " takes no temperature (it has no thermal strain)");
    if (!heated.insert(temperature.block).second)
      throw InputError("two temperatures given for block '" + temperature.block + "'");
  }
  checkAxisymmetricModel(model_);
  checkPlaneStressModel(model_);
}

std::optional<double> Problem::blockTemperature(int block, double t) const {
  const BlockTemperature* temperature = blockTemperature_[block];
  if (!temperature) return std::nullopt;
  return temperature->at(*blockMaterial_[block]->referenceTemperature(), t);
}

void Problem::buildGraph() {
  std::vector<std::vector<int>> elementNodes, partnerNodes;
  elementNodes.reserve(elements_.size());
  for (const auto& e : elements_)
    elementNodes.push_back(e.nodes);
  // A tie's dependent node moves its row and column to its partners: widen its elements' graph.
  if (!linearConstraints_->tiedNodes().empty())
    for (const auto& e : elements_) {
      partnerNodes.emplace_back();
      for (int n : e.nodes)
        for (std::int64_t partner : linearConstraints_->partnerNodes(dofs_->overlapNodes()[n]))
          partnerNodes.back().push_back(dofs_->overlapNodeIndex(partner));
    }
  assembler_ = std::make_unique<MatrixAssembler>(*dofs_, elementNodes, partnerNodes);
  exporter_ = Teuchos::rcp(new Export(dofs_->overlapMap(), dofs_->ownedMap()));
  importer_ = Teuchos::rcp(new Import(dofs_->ownedMap(), dofs_->overlapMap()));
}

const Teuchos::RCP<Matrix>& Problem::tangent() const {
  return assembler_->matrix();
}

const std::vector<std::string>& Problem::followerLoads() const {
  return surfaceLoads_->followerLoads();
}

Teuchos::RCP<Vector> Problem::createVector() const {
  return Teuchos::rcp(new Vector(dofs_->ownedMap()));
}

Teuchos::RCP<Vector> Problem::overlapCopy(const Vector& u) const {
  auto v = Teuchos::rcp(new Vector(dofs_->overlapMap()));
  v->doImport(u, *importer_, Tpetra::INSERT);
  return v;
}

void Problem::applyDirichlet(double t, Vector& u) const {
  auto data = u.getDataNonConst(0);
  const Mesh& mesh = *model_.mesh;
  for (const auto& c : constraints_) {
    const auto& bc = model_.dirichlet[c.condition];
    data[c.lid] =
        bc.field ? bc.field(&mesh.coords[3 * c.node], c.component, t) : bc.value * bc.function(t);
  }
  linearConstraints_->impose(t, data.getRawPtr());
}

void Problem::completeIncrement(Vector& dx) const {
  linearConstraints_->project(dx.getDataNonConst(0).getRawPtr());
}

double Problem::internalForceNorm() const {
  if (internalForceNorm_ >= 0) return internalForceNorm_;
  Vector overlap(dofs_->overlapMap()), owned(dofs_->ownedMap());
  auto data = overlap.getDataNonConst(0);
  std::copy(internalForces_.begin(), internalForces_.end(), data.begin());
  owned.doExport(overlap, *exporter_, Tpetra::ADD);
  internalForceNorm_ = owned.norm2();
  return internalForceNorm_;
}

double Problem::modelSize() const {
  // Twice the largest distance of a node from the nodes' centroid: a box's diagonal, and unlike
  // the bounding box's diagonal the same for a rotated copy of the model (so Newton is too).
  const std::vector<double>& coords = model_.mesh->coords;
  const std::size_t nodes = coords.size() / 3;
  if (nodes == 0) return 0;
  std::array<double, 3> centroid{0, 0, 0};
  for (std::size_t i = 0; i < coords.size(); ++i)
    centroid[i % 3] += coords[i] / nodes;
  double largest = 0;
  for (std::size_t n = 0; n < nodes; ++n)
    largest =
        std::max(largest, std::hypot(coords[3 * n] - centroid[0], coords[3 * n + 1] - centroid[1],
                                     coords[3 * n + 2] - centroid[2]));
  return 2 * largest;
}

void Problem::addExternalForces(double t, const double* u, std::vector<double>& f) const {
  const Mesh& mesh = *model_.mesh;
  surfaceLoads_->addForces(t, u, f);
  nodal_->addPointLoads(t, f);
  std::vector<double> x, fe;
  for (const auto& body : model_.bodyForces) {
    const double scale = body.function(t);
    for (const auto& e : elements_) {
      const auto& block = mesh.blocks[e.block];
      if (!body.block.empty() && block.name != body.block) continue;
      gatherCoordinates(e.nodes, x);
      fe.assign(e.rows.size(), 0.0);
      if (body.field) {
        kernels_[e.kernel]->bodyForce(
            x.data(), [&](const double* p, double* b) { body.field(p, t, b); }, fe.data());
      } else {
        double b[3];
        for (int i = 0; i < 3; ++i)
          b[i] = body.value[i] * scale;
        kernels_[e.kernel]->bodyForce(x.data(), b, fe.data());
      }
      for (std::size_t i = 0; i < e.rows.size(); ++i)
        f[e.rows[i]] += fe[i];
    }
  }
  if (centrifugal_.empty()) return;
  for (const auto& e : elements_) {
    fe.assign(e.rows.size(), 0.0);
    addCentrifugal(e, t, u, fe.data(), nullptr);
    for (std::size_t i = 0; i < e.rows.size(); ++i)
      f[e.rows[i]] += fe[i];
  }
}

void Problem::addCentrifugal(const LocalElement& e, double t, const double* u, double* f,
                             double* k) const {
  const int dim = model_.mesh->dim;
  const int numNodes = static_cast<int>(e.nodes.size()), nd = numNodes * dim;
  std::vector<double> x, mass;
  for (std::size_t l = 0; l < centrifugal_.size(); ++l) {
    const CentrifugalLoad& load = model_.centrifugalLoads[l];
    if (!load.block.empty() && model_.mesh->blocks[e.block].name != load.block) continue;
    const bool follower = load.follower == SurfaceLoad::Follower::Yes ||
                          (load.follower == SurfaceLoad::Follower::Automatic &&
                           blockMaterial_[e.block]->kinematics() == Kinematics::FiniteStrain);
    if (!follower && !f) continue;
    if (mass.empty()) {
      gatherCoordinates(e.nodes, x);
      mass.assign(static_cast<std::size_t>(nd) * nd, 0.0);
      massKernels_[e.kernel]->add(x.data(), 1.0, false, mass.data());
    }
    if (f) {
      // A follower load acts at the current positions X + u.
      std::vector<double> position = x;
      if (follower)
        for (int a = 0; a < numNodes; ++a)
          for (int i = 0; i < dim; ++i)
            position[3 * a + i] += u[e.rows[a * dim + i]];
      centrifugal_[l].addForce(mass.data(), position.data(), numNodes, t, f);
    }
    if (k && follower) centrifugal_[l].addStiffness(mass.data(), numNodes, t, k);
  }
}

void Problem::assemble(const Vector& u, double t, Vector* residual, bool withTangent) {
  auto uOverlap = overlapCopy(u);
  auto uo = uOverlap->getData(0);
  std::vector<double> r(residual ? dofs_->overlapMap()->getNodeNumElements() : 0, 0.0);
  const double c = inertia_.coefficient;
  // A solid whose tangent never changes (every element linear, no mass or centrifugal term)
  // adds its element matrices once: later tangents start from their kept sum. Measured on the
  // 2D Hertz scene's runs and the peers' 125 730-dof tet10 model (doc/performance.md).
  const bool constantBulk = withTangent && allLinear_ && c == 0 && centrifugal_.empty();
  const bool fromKept = constantBulk && assembler_->keepsValues();
  const bool addElements = withTangent && !fromKept;
  if (fromKept)
    assembler_->beginFromKept();
  else if (withTangent)
    assembler_->begin();
  const bool inertiaForce = c > 0 && inertia_.reference && residual;
  const double* reference = inertiaForce ? inertia_.reference->getData(0).getRawPtr() : nullptr;
  std::vector<double> x, ue, fe, ke, me, deformation;
  int failureCode = 0;  // 1: material-update-failed, 2: inverted-element
  std::string failureMessage;
  for (auto& e : elements_) {
    if (!residual && !addElements) break;  // the kept tangent is all there is to do
    const std::size_t nd = e.rows.size();
    gatherCoordinates(e.nodes, x);
    ue.resize(nd);
    for (std::size_t i = 0; i < nd; ++i)
      ue[i] = uo[e.rows[i]];
    fe.assign(nd, 0.0);
    if (addElements) ke.assign(nd * nd, 0.0);
    try {
      if (e.linear) {
        if (e.stiffness.empty()) {
          e.stiffness.assign(nd * nd, 0.0);
          kernels_[e.kernel]->compute(x.data(), ue.data(), *blockMaterial_[e.block], nullptr,
                                      nullptr, fe.data(), e.stiffness.data());
        }
        linearElementForce(e.stiffness, ue, kernels_[e.kernel]->dim(), model_.axisymmetric,
                           deformation, fe);
        if (addElements) ke.assign(e.stiffness.begin(), e.stiffness.end());
      } else {
        kernels_[e.kernel]->compute(x.data(), ue.data(), *blockMaterial_[e.block],
                                    e.stateOld.empty() ? nullptr : e.stateOld.data(),
                                    e.stateNew.empty() ? nullptr : e.stateNew.data(), fe.data(),
                                    withTangent ? ke.data() : nullptr,
                                    blockTemperature(e.block, t));
      }
    } catch (const ElementUpdateError& err) {
      // Not thrown on: the other ranks are on their way to the collective calls below. The
      // NaN stops every Newton variant; assemblyFailure() says why.
      if (failureCode == 0) {
        failureCode = err.code() == "inverted-element" ? 2 : 1;
        failureMessage = elementLabel(*model_.mesh, e.block, e.cell) + ", quadrature point " +
                         std::to_string(err.point()) + ": " + err.what();
      }
      fe.assign(nd, std::numeric_limits<double>::quiet_NaN());
      if (withTangent) ke.assign(nd * nd, 0.0);
    }
    if (c > 0 && (inertiaForce || withTangent)) {
      me.assign(nd * nd, 0.0);
      massKernels_[e.kernel]->add(x.data(), blockMaterial_[e.block]->density(), inertia_.lumped,
                                  me.data());
      for (std::size_t i = 0; i < nd; ++i)
        for (std::size_t j = 0; j < nd; ++j) {
          const double cm = c * me[i * nd + j];
          if (withTangent) ke[i * nd + j] += cm;
          if (inertiaForce) fe[i] += cm * (ue[j] - reference[e.rows[j]]);
        }
    }
    if (withTangent && !centrifugal_.empty())
      addCentrifugal(e, t, uo.getRawPtr(), nullptr, ke.data());
    if (residual)
      for (std::size_t i = 0; i < nd; ++i)
        r[e.rows[i]] += fe[i];
    // Element-level elimination of constrained rows and columns (see Problem.hpp).
    if (addElements) assembler_->add(&e - elements_.data(), ke.data(), constrained_);
  }
  if (constantBulk && !fromKept) assembler_->keepValues();
  if (withTangent) {
    surfaceLoads_->addStiffness(t, uo.getRawPtr(), *assembler_, constrained_);
    nodal_->addSpringStiffness(*assembler_, constrained_);
    for (const auto& c : constraints_)
      assembler_->addDiagonal(c.lid, 1.0);
    assembler_->end();
  }
  int globalFailure = 0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, failureCode, Teuchos::outArg(globalFailure));
  assemblyFailure_ = {};
  if (globalFailure > 0) {
    assemblyFailure_.code = globalFailure == 2 ? "inverted-element" : "material-update-failed";
    assemblyFailure_.message =
        failureCode == globalFailure ? failureMessage : "an element of another rank failed";
  }
  Matrix* reducedTangent = withTangent && !deferConstraints_ ? assembler_->matrix().get() : nullptr;
  if (!residual) {
    linearConstraints_->reduce(reducedTangent, nullptr);
    return;
  }

  // R = f_int + k u - f_ext, summed over ranks into owned entries.
  nodal_->addSpringForces(uo.getRawPtr(), r);
  std::vector<double> fext(r.size(), 0.0);
  addExternalForces(t, uo.getRawPtr(), fext);
  Vector rOverlap(dofs_->overlapMap());
  {
    auto data = rOverlap.getDataNonConst(0);
    std::copy(r.begin(), r.end(), data.begin());
  }
  internalForces_ = r;
  internalForceNorm_ = -1;
  {
    auto data = rOverlap.getDataNonConst(0);
    for (std::size_t i = 0; i < r.size(); ++i)
      data[i] = r[i] - fext[i];
  }
  residual->putScalar(0.0);
  residual->doExport(rOverlap, *exporter_, Tpetra::ADD);

  // The reactions, then the springs' forces, summed over ranks in one reduction.
  auto res = residual->getDataNonConst(0);
  const std::size_t reactionSums = 3 * reactions_.size();
  std::vector<double> sums(reactionSums + 3 * springForces_.size(), 0.0), global(sums.size());
  for (const auto& c : constraints_) {
    sums[3 * c.condition + c.component] += res[c.lid];
    res[c.lid] = 0.0;
  }
  const auto springs = nodal_->localSpringForces(uo.getRawPtr());
  for (std::size_t s = 0; s < springs.size(); ++s)
    std::copy(springs[s].begin(), springs[s].end(), sums.begin() + reactionSums + 3 * s);
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(sums.size()), sums.data(),
                     global.data());
  for (std::size_t d = 0; d < model_.dirichlet.size(); ++d)
    for (int c = 0; c < 3; ++c)
      reactions_[d].force[c] = global[3 * d + c];
  for (std::size_t s = 0; s < springForces_.size(); ++s)
    for (int c = 0; c < 3; ++c)
      springForces_[s].force[c] = global[reactionSums + 3 * s + c];
  if (linearConstraints_->empty()) return;
  constraintReactions(*residual, false);
  if (!deferConstraints_) linearConstraints_->reduce(reducedTangent, residual);
}

void Problem::addToReactions(const Vector& forces) {
  const auto f = forces.getData(0);
  std::vector<double> sums(3 * model_.dirichlet.size(), 0.0), global(sums.size(), 0.0);
  for (const auto& c : constraints_)
    sums[3 * c.condition + c.component] += f[c.lid];
  if (!sums.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(sums.size()), sums.data(),
                       global.data());
  for (std::size_t d = 0; d < model_.dirichlet.size(); ++d)
    for (int c = 0; c < 3; ++c)
      reactions_[d].force[c] += global[3 * d + c];
  constraintReactions(forces, true);
}

void Problem::constraintReactions(const Vector& forces, bool add) {
  if (linearConstraints_->empty()) return;
  std::vector<std::array<double, 3>> all = linearConstraints_->reactions(forces);
  const std::vector<std::array<double, 3>> ties = linearConstraints_->tieForces(forces);
  all.insert(all.end(), ties.begin(), ties.end());
  for (std::size_t k = 0; k < all.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      double& force = reactions_[model_.dirichlet.size() + k].force[c];
      force = add ? force + all[k][c] : all[k][c];
    }
}

void Problem::commitState() {
  for (auto& e : elements_) {
    if (e.stateNew.empty()) continue;
    const Material& material = *blockMaterial_[e.block];
    const int ss = material.stateSize();
    e.plastic = false;
    for (std::size_t q = 0; q * ss < e.stateNew.size(); ++q)
      e.plastic = e.plastic || material.equivalentPlasticStrain(&e.stateNew[q * ss]) >
                                   material.equivalentPlasticStrain(&e.stateOld[q * ss]);
    e.stateOld = e.stateNew;
  }
}

std::string Problem::massUnavailable() const {
  for (const auto& [block, material] : model_.materials)
    if (!(material->density() > 0))
      return "the material of block '" + block + "' has density 0: give it a density";
  return "";
}

void Problem::setInertia(const InertiaTerm& inertia) {
  if (inertia.coefficient != 0) {
    const std::string missing = massUnavailable();
    if (!missing.empty()) throw InputError("an inertia term needs a mass, but " + missing);
  }
  inertia_.coefficient = inertia.coefficient;
  inertia_.lumped = inertia.lumped;
  // The reference on the overlap map: the elements read their ghost nodes' values too.
  inertia_.reference = inertia.reference ? overlapCopy(*inertia.reference) : Teuchos::null;
}

}  // namespace contactlab
