#include "core/problem/LinearConstraints.hpp"

#include "base/InputError.hpp"
#include "base/NumberText.hpp"
#include "core/materials/Tensor3.hpp"
#include "core/problem/DofMap.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

namespace contactlab {
namespace {

constexpr double kPlaneTolerance = 1e-6;  // of the group's extent
constexpr double kAxisTolerance = 1e-12;  // a unit normal this close to an axis is that axis

std::string vectorText(const std::array<double, 3>& v) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "[%.6g, %.6g, %.6g]", v[0], v[1], v[2]);
  return buffer;
}

// The position of column `col` in the entries [begin, end) of a row, or -1.
std::ptrdiff_t find(const LO* begin, const LO* end, LO col) {
  const LO* it = std::find(begin, end, col);
  return it == end ? -1 : it - begin;
}

// A tie with a right side whose equation made nothing dependent: its dofs are all prescribed,
// or it follows from other equations, and the right sides may then contradict one another.
void refuseRedundantRightSides(const SolidModel& model, const std::vector<TieEquation>& ties,
                               const std::vector<RedundantEquation>& redundant) {
  for (const RedundantEquation& r : redundant)
    for (const auto& [e, w] : r.combination) {
      if (ties[e].tie < 0) continue;  // a symmetry plane's: no right side
      const TieCondition& tie = model.ties[ties[e].tie];
      if (tie.value == 0 || w == 0) continue;
      const TieEquation& equation = ties[r.equation];
      const std::string own =
          equation.tie >= 0 ? "tie '" + model.ties[equation.tie].name + "'"
                            : "symmetry condition '" + model.symmetries[equation.plane].name + "'";
      const MeshDof& dof = equation.dofs.front();
      throw InputError(own + ": the equation of node " +
                       std::to_string(model.mesh->nodeId(dof.first)) + " (component " +
                       "xyz"[dof.second] +
                       ") leaves no dof to make dependent (every dof in it is " +
                       "prescribed, or it follows from other ties' equations), and tie '" +
                       tie.name + "' has a right side (Value " + numberText(tie.value) +
                       "), which could contradict them; remove the duplicate tie or the " +
                       "Dirichlet condition on its nodes");
    }
}

}  // namespace

std::array<double, 3> symmetryPlaneNormal(const Mesh& mesh, const SymmetryCondition& condition) {
  const std::string what =
      "symmetry condition '" + condition.name + "' (group '" + condition.group + "')";
  std::vector<std::int64_t> nodes;
  try {
    nodes = mesh.boundaryNodes(condition.group);
  } catch (const std::invalid_argument& e) {
    throw InputError(what + ": " + e.what());
  }
  if (nodes.empty()) throw InputError(what + ": the group has no nodes");
  std::array<double, 3> centre{0, 0, 0};
  for (auto n : nodes)
    for (int i = 0; i < 3; ++i)
      centre[i] += mesh.coords[3 * n + i] / static_cast<double>(nodes.size());
  double extent = 0;
  tensor3::Mat3 scatter{};
  for (auto n : nodes) {
    double d[3];
    for (int i = 0; i < 3; ++i)
      d[i] = mesh.coords[3 * n + i] - centre[i];
    extent = std::max(extent, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        scatter[i * 3 + j] += d[i] * d[j];
  }
  std::array<double, 3> n = condition.normal;
  const double given = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (given > 0) {
    if (mesh.dim == 2 && n[2] != 0)
      throw InputError(what + ": Normal " + vectorText(n) +
                       " has a z component; a 2D model's symmetry line has a normal in the xy "
                       "plane");
    for (double& v : n)
      v /= given;
  } else {
    // The fitted plane's normal: the direction of least spread (in 2D, within the xy plane).
    if (mesh.dim == 2) scatter[8] = 1.0 + scatter[0] + scatter[4];
    std::array<double, 3> values;
    tensor3::Mat3 q;
    if (!tensor3::symmetricEigen(scatter, values, q))
      throw InputError(what + ": cannot fit a plane through its nodes; give Normal");
    int least = 0;
    for (int a = 1; a < 3; ++a)
      if (values[a] < values[least]) least = a;
    for (int i = 0; i < 3; ++i)
      n[i] = q[i * 3 + least];
    // A line of nodes in 3D (or a single node) leaves the plane undetermined.
    int flat = 0;
    for (double v : values)
      if (v <= std::pow(kPlaneTolerance * extent, 2) * static_cast<double>(nodes.size())) ++flat;
    if (nodes.size() < static_cast<std::size_t>(mesh.dim) || flat > (mesh.dim == 2 ? 2 : 1))
      throw InputError(what +
                       ": its nodes do not determine a plane (too few, or in a line); "
                       "give Normal");
    // Sign: the largest component positive, so the fit is reproducible.
    int largest = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(n[i]) > std::abs(n[largest])) largest = i;
    if (n[largest] < 0)
      for (double& v : n)
        v = -v;
  }
  for (auto node : nodes) {
    double distance = 0;
    for (int i = 0; i < 3; ++i)
      distance += n[i] * (mesh.coords[3 * node + i] - centre[i]);
    if (std::abs(distance) > kPlaneTolerance * std::max(extent, 1e-300))
      throw InputError(what + ": node " + std::to_string(node + 1) + " is " +
                       std::to_string(std::abs(distance)) + " off the plane of normal " +
                       vectorText(n) + " through the group's centre; a symmetry group must be " +
                       "planar" + (given > 0 ? " and normal to Normal" : ""));
  }
  return n;
}

void resolveSymmetryConditions(SolidModel& model) {
  std::vector<SymmetryCondition> inclined;
  for (SymmetryCondition s : model.symmetries) {
    s.normal = symmetryPlaneNormal(*model.mesh, s);
    int axis = -1;
    for (int i = 0; i < 3; ++i)
      if (std::abs(s.normal[i]) >= 1.0 - kAxisTolerance) axis = i;
    if (axis < 0) {
      inclined.push_back(s);
      continue;
    }
    model.axisSymmetries.push_back(s);
    DirichletCondition bc;
    bc.name = s.name;
    bc.group = s.group;
    bc.components = {axis};
    bc.function.kind = LoadFunction::Kind::Constant;
    model.dirichlet.push_back(bc);
  }
  model.symmetries = inclined;
}

LinearConstraints::LinearConstraints(const SolidModel& model, const DofMap& dofs,
                                     const std::vector<TieEquation>& ties)
    : dim_(model.mesh->dim), numConditions_(model.symmetries.size()), comm_(dofs.comm()) {
  const Mesh& mesh = *model.mesh;
  std::set<MeshDof> fixed;  // of a Dirichlet condition
  for (const auto& bc : model.dirichlet)
    for (auto node : mesh.boundaryNodes(bc.group))
      for (int c : bc.components)
        fixed.insert({node, c});
  std::set<std::int64_t> tiedNodes;  // the planes' equations add none: theirs are tied
  for (const TieEquation& e : ties)
    for (const MeshDof& d : e.dofs)
      tiedNodes.insert(d.first);
  tiedNodes_.assign(tiedNodes.begin(), tiedNodes.end());
  // The planes' equations at tied nodes, eliminated with the ties' (addTies).
  std::vector<TieEquation> equations;
  for (const SymmetryCondition& s : model.symmetries)
    conditionNormals_.push_back(s.normal);
  // The planes through each node, without repeats (a node on two groups of one plane).
  std::map<std::int64_t, std::vector<std::pair<int, std::array<double, 3>>>> planes;
  for (std::size_t s = 0; s < model.symmetries.size(); ++s) {
    const auto& n = model.symmetries[s].normal;
    for (auto node : mesh.boundaryNodes(model.symmetries[s].group)) {
      if (dofs.globalNode(node) < 0) continue;
      auto& list = planes[node];
      bool repeated = false;
      for (const auto& [condition, m] : list)
        repeated = repeated || std::abs(n[0] * m[0] + n[1] * m[1] + n[2] * m[2]) > 1 - 1e-10;
      if (!repeated) list.push_back({static_cast<int>(s), n});
    }
  }
  for (const SymmetryCondition& axis : model.axisSymmetries)
    for (auto node : mesh.boundaryNodes(axis.group))
      if (dofs.globalNode(node) >= 0) axisPlanes_[node].push_back(axis.normal);
  const int rank = comm_->getRank();
  for (const auto& [node, list] : planes) {
    const bool owned = dofs.nodeOwner(node) == rank;
    const int overlap = dofs.overlapNodeIndex(node);
    nodes_.push_back(node);
    normals_.emplace_back();
    for (const auto& entry : list)
      normals_.back().push_back(entry.second);
    if (tiedNodes.count(node)) {
      for (const auto& [condition, normal] : list) {
        TieEquation e;
        e.tie = -1;
        e.plane = condition;
        for (int c = 0; c < dim_; ++c)
          if (normal[c] != 0) e.dofs.push_back({node, c}), e.coefficients.push_back(normal[c]);
        equations.push_back(e);
      }
      continue;
    }
    if (owned) ownedNodes_.push_back({static_cast<LO>(overlap * dim_), list});
    // Reduced row echelon form of the planes' rows over the free components (full pivoting):
    // each pivot row r then reads u_k + sum_j a_rj u_j = 0 over the non-pivot components j.
    std::vector<std::array<double, 3>> rows;
    for (const auto& entry : list)
      rows.push_back(entry.second);
    std::vector<int> pivots;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      double best = 1e-8;
      std::size_t bestRow = rows.size();
      int bestCol = -1;
      for (std::size_t i = r; i < rows.size(); ++i)
        for (int c = 0; c < dim_; ++c)
          if (!fixed.count({node, c}) &&
              std::find(pivots.begin(), pivots.end(), c) == pivots.end() &&
              std::abs(rows[i][c]) > best) {
            best = std::abs(rows[i][c]);
            bestRow = i;
            bestCol = c;
          }
      if (bestCol < 0) {
        rows.resize(r);  // the rest is implied by the pivots and the Dirichlet components
        break;
      }
      std::swap(rows[r], rows[bestRow]);
      const double p = rows[r][bestCol];
      for (double& v : rows[r])
        v /= p;
      for (std::size_t i = 0; i < rows.size(); ++i) {
        if (i == r) continue;
        const double f = rows[i][bestCol];
        for (int c = 0; c < 3; ++c)
          rows[i][c] -= f * rows[r][c];
      }
      pivots.push_back(bestCol);
    }
    const GO gidBase = dofs.globalNode(node) * dim_;
    for (std::size_t r = 0; r < pivots.size(); ++r) {
      const int k = pivots[r];
      Dependent d{owned ? static_cast<LO>(overlap * dim_ + k) : LO(-1), gidBase + k, {}, {}};
      for (int j = 0; j < dim_; ++j) {
        if (std::find(pivots.begin(), pivots.end(), j) != pivots.end() || rows[r][j] == 0) continue;
        d.terms.push_back({owned ? static_cast<LO>(overlap * dim_ + j) : LO(-1), gidBase + j,
                           -rows[r][j], fixed.count({node, j}) > 0});
      }
      all_.push_back(d);
    }
  }
  equations.insert(equations.end(), ties.begin(), ties.end());
  addTies(model, dofs, equations, fixed);
  for (std::size_t d = 0; d < all_.size(); ++d)
    dependentOf_[all_[d].gid] = d;
  const int local = all_.empty() ? 0 : 1;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, local, Teuchos::outArg(anywhere_));
}

void LinearConstraints::addTies(const SolidModel& model, const DofMap& dofs,
                                const std::vector<TieEquation>& ties,
                                const std::set<MeshDof>& fixed) {
  for (const TieEquation& e : ties)
    for (const MeshDof& d : e.dofs)
      if (e.tie >= 0 && dofs.globalNode(d.first) < 0)
        throw InputError("tie '" + model.ties[e.tie].name + "': node " +
                         std::to_string(model.mesh->nodeId(d.first)) + " is on no element");
  const int rank = comm_->getRank();
  const auto lidOf = [&](const MeshDof& d) {
    return dofs.nodeOwner(d.first) == rank
               ? static_cast<LO>(dofs.overlapNodeIndex(d.first) * dim_ + d.second)
               : LO(-1);
  };
  const auto gidOf = [&](const MeshDof& d) { return dofs.globalNode(d.first) * dim_ + d.second; };
  numTies_ = model.ties.size();
  for (const TieCondition& tie : model.ties)
    tieFunctions_.push_back(tie.function);
  std::vector<RedundantEquation> redundant;
  const std::vector<TiedDof> dependents = eliminateTies(ties, fixed, &redundant);
  refuseRedundantRightSides(model, ties, redundant);
  for (const TiedDof& tiedDof : dependents) {
    Dependent d{lidOf(tiedDof.dof), gidOf(tiedDof.dof), {}, {}};
    for (const auto& [e, w] : tiedDof.equations) {
      if (ties[e].plane >= 0) {
        if (d.lid >= 0) planeForceTerms_.push_back({d.lid, ties[e].plane, w});
        continue;
      }
      const int tie = ties[e].tie;
      if (d.lid >= 0)
        tieForceTerms_.push_back(
            {d.lid, tie, ties[e].dofs.front().second, w * model.ties[tie].coefficients.front()});
      if (model.ties[tie].value != 0) d.rightSide.push_back({tie, w * model.ties[tie].value});
    }
    auto& partners = partners_[tiedDof.dof.first];
    for (const auto& [dof, c] : tiedDof.terms) {
      d.terms.push_back({lidOf(dof), gidOf(dof), c, fixed.count(dof) > 0});
      if ((d.lid < 0) != (d.terms.back().lid < 0))
        throw std::logic_error("LinearConstraints: a tie's nodes are not owned together");
      if (dof.first != tiedDof.dof.first) partners.push_back(dof.first);
    }
    std::sort(partners.begin(), partners.end());
    partners.erase(std::unique(partners.begin(), partners.end()), partners.end());
    all_.push_back(d);
  }
}

std::vector<GO> LinearConstraints::partnerDofs(GO gid) const {
  const auto it = dependentOf_.find(gid);
  if (it == dependentOf_.end()) return {};
  std::vector<GO> out;
  for (const Term& t : all_[it->second].terms)
    if (!t.prescribed) out.push_back(t.gid);
  return out;
}

std::vector<std::int64_t> LinearConstraints::partnerNodes(std::int64_t node) const {
  const auto it = partners_.find(node);
  return it == partners_.end() ? std::vector<std::int64_t>{} : it->second;
}

std::vector<std::array<double, 3>> LinearConstraints::allPlaneNormals(std::int64_t node) const {
  auto normals = planeNormals(node);
  const auto it = axisPlanes_.find(node);
  if (it != axisPlanes_.end()) normals.insert(normals.end(), it->second.begin(), it->second.end());
  return normals;
}

std::vector<std::array<double, 3>> LinearConstraints::planeNormals(std::int64_t node) const {
  const auto it = std::lower_bound(nodes_.begin(), nodes_.end(), node);
  if (it == nodes_.end() || *it != node) return {};
  return normals_[static_cast<std::size_t>(it - nodes_.begin())];
}

void LinearConstraints::impose(double t, double* owned) const {
  project(owned);
  for (const Dependent& d : all_)
    if (d.lid >= 0)
      for (const auto& [tie, weight] : d.rightSide)
        owned[d.lid] += weight * tieFunctions_[static_cast<std::size_t>(tie)](t);
}

void LinearConstraints::project(double* owned) const {
  for (const Dependent& d : all_) {
    if (d.lid < 0) continue;
    double v = 0;
    for (const Term& t : d.terms)
      v += t.c * owned[t.lid];
    owned[d.lid] = v;
  }
}

void LinearConstraints::reduce(Matrix* matrix, Vector* residual) const {
  if (!anywhere_) return;
  if (residual) {
    auto r = residual->getDataNonConst(0);
    for (const Dependent& d : all_) {
      if (d.lid < 0) continue;
      for (const Term& t : d.terms)
        if (!t.prescribed) r[t.lid] += t.c * r[d.lid];
      r[d.lid] = 0;
    }
  }
  if (!matrix) return;
  Matrix& tangent = *matrix;
  tangent.resumeFill();
  const auto local = tangent.getLocalMatrixHost();
  double* values = local.values.data();
  const auto& rowMap = local.graph.row_map;
  const LO* entries = local.graph.entries.data();
  const auto colMap = tangent.getColMap();
  // Columns first (K T), then rows (T^T K T): a dependent column's entries move to its
  // partners' columns in every row.
  // By local column: a lookup per matrix entry (a hash lookup each cost 4.6 % of the hex27
  // tube-expansion-3d run).
  std::vector<const Dependent*> dependentColumn(tangent.getColMap()->getNodeNumElements(), nullptr);
  for (const Dependent& d : all_) {
    const LO col = colMap->getLocalElement(d.gid);
    if (col != Teuchos::OrdinalTraits<LO>::invalid()) dependentColumn[col] = &d;
  }
  const auto missing = [](const char* what) {
    throw std::logic_error(std::string("LinearConstraints: the matrix graph lacks ") + what);
  };
  const LO numRows = static_cast<LO>(tangent.getNodeNumRows());
  for (LO row = 0; row < numRows; ++row) {
    const LO *begin = entries + rowMap(row), *end = entries + rowMap(row + 1);
    double* rowValues = values + rowMap(row);
    for (const LO* e = begin; e != end; ++e) {
      const Dependent* dependent = dependentColumn[*e];
      if (!dependent) continue;
      const double v = rowValues[e - begin];
      if (v == 0) continue;
      for (const Term& t : dependent->terms) {
        if (t.prescribed) continue;
        const std::ptrdiff_t at = find(begin, end, colMap->getLocalElement(t.gid));
        if (at < 0) missing("a partner column of a symmetry node");
        rowValues[at] += t.c * v;
      }
      rowValues[e - begin] = 0;
    }
  }
  for (const Dependent& d : all_) {
    if (d.lid < 0) continue;
    const LO *kBegin = entries + rowMap(d.lid), *kEnd = entries + rowMap(d.lid + 1);
    double* kValues = values + rowMap(d.lid);
    for (const Term& t : d.terms) {
      if (t.prescribed) continue;
      const LO *jBegin = entries + rowMap(t.lid), *jEnd = entries + rowMap(t.lid + 1);
      double* jValues = values + rowMap(t.lid);
      for (const LO* e = kBegin; e != kEnd; ++e) {
        const double v = kValues[e - kBegin];
        if (v == 0) continue;
        const std::ptrdiff_t at = find(jBegin, jEnd, *e);
        if (at < 0) missing("a column of a symmetry node's dependent row in its partner's row");
        jValues[at] += t.c * v;
      }
    }
    std::fill(kValues, kValues + (kEnd - kBegin), 0.0);
    const std::ptrdiff_t diagonal = find(kBegin, kEnd, colMap->getLocalElement(d.gid));
    if (diagonal < 0) missing("the diagonal of a symmetry node's dependent row");
    kValues[diagonal] = 1.0;
  }
  tangent.fillComplete(tangent.getDomainMap(), tangent.getRangeMap());
}

std::vector<std::array<double, 3>> LinearConstraints::tieForces(const Vector& residual) const {
  std::vector<std::array<double, 3>> local(numTies_), global(numTies_);
  const auto r = residual.getData(0);
  for (const TieForceTerm& t : tieForceTerms_)
    local[t.tie][t.component] += t.w * r[t.lid];
  if (numTies_ > 0)
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(3 * numTies_),
                       local.front().data(), global.front().data());
  return global;
}

std::vector<std::array<double, 3>> LinearConstraints::reactions(const Vector& residual) const {
  std::vector<std::array<double, 3>> local(numConditions_), global(numConditions_);
  const auto r = residual.getData(0);
  for (const OwnedNode& n : ownedNodes_) {
    std::array<double, 3> force{0, 0, 0};
    for (int c = 0; c < dim_; ++c)
      force[c] = r[n.firstLid + c];
    // force = sum_s alpha_s n_s, by the normal equations G alpha = N^T force (G = N^T N, at most
    // 3 x 3 and regular: the planes through a node are distinct).
    const std::size_t m = n.planes.size();
    double g[3][4];
    for (std::size_t a = 0; a < m; ++a) {
      const auto& na = n.planes[a].second;
      for (std::size_t b = 0; b < m; ++b) {
        const auto& nb = n.planes[b].second;
        g[a][b] = na[0] * nb[0] + na[1] * nb[1] + na[2] * nb[2];
      }
      g[a][m] = na[0] * force[0] + na[1] * force[1] + na[2] * force[2];
    }
    for (std::size_t p = 0; p < m; ++p)  // Gauss-Jordan, G is symmetric positive definite
      for (std::size_t a = 0; a < m; ++a) {
        if (a == p) continue;
        const double f = g[a][p] / g[p][p];
        for (std::size_t b = p; b <= m; ++b)
          g[a][b] -= f * g[p][b];
      }
    for (std::size_t a = 0; a < m; ++a) {
      const double alpha = g[a][m] / g[a][a];
      for (int c = 0; c < 3; ++c)
        local[n.planes[a].first][c] += alpha * n.planes[a].second[c];
    }
  }
  // At tied nodes: the planes' equations' multipliers along their normals.
  for (const PlaneForceTerm& t : planeForceTerms_)
    for (int c = 0; c < 3; ++c)
      local[t.condition][c] += t.w * conditionNormals_[t.condition][c] * r[t.lid];
  // std::array<double, 3> has no padding: the lists are 3 n contiguous doubles.
  if (numConditions_ > 0)
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(3 * numConditions_),
                       local.front().data(), global.front().data());
  return global;
}

}  // namespace contactlab
