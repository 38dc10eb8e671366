#include "core/problem/TieEquations.hpp"

#include "base/InputError.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

namespace contactlab {
namespace {

constexpr double kMatchTolerance = 1e-6;  // of the tie's extent
constexpr double kDropTolerance = 1e-12;  // of an equation's largest coefficient

std::array<double, 3> centroid(const Mesh& mesh, const std::vector<std::int64_t>& nodes) {
  std::array<double, 3> c{0, 0, 0};
  for (auto n : nodes)
    for (int i = 0; i < 3; ++i)
      c[i] += mesh.coords[3 * n + i] / static_cast<double>(nodes.size());
  return c;
}

double distance(const Mesh& mesh, std::int64_t node, const std::array<double, 3>& x) {
  double d2 = 0;
  for (int i = 0; i < 3; ++i)
    d2 += std::pow(mesh.coords[3 * node + i] - x[i], 2);
  return std::sqrt(d2);
}

// A group's nodes in a uniform grid of cells no smaller than twice the matching tolerance (and
// about one node each on a line in 2D or a surface in 3D), so that a node within the tolerance
// of a point is in the point's cell or a neighbour.
class NodeGrid {
 public:
  NodeGrid(const Mesh& mesh, const std::vector<std::int64_t>& nodes, double extent,
           double tolerance)
      : mesh_(mesh), nodes_(nodes) {
    const double n = static_cast<double>(nodes.size());
    cell_ =
        std::max({2 * tolerance, extent / std::pow(n, 1.0 / std::max(mesh.dim - 1, 1)), 1e-300});
    for (std::size_t q = 0; q < nodes.size(); ++q)
      cells_[key(&mesh.coords[3 * nodes[q]], 0, 0, 0)].push_back(q);
  }

  // The index in `nodes` of the node nearest to x within `tolerance`, or -1.
  std::ptrdiff_t nearest(const std::array<double, 3>& x, double tolerance) const {
    std::ptrdiff_t best = -1;
    double bestDistance = tolerance;
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j)
        for (int k = -1; k <= 1; ++k) {
          const auto cell = cells_.find(key(x.data(), i, j, k));
          if (cell == cells_.end()) continue;
          for (std::size_t q : cell->second) {
            const double d = distance(mesh_, nodes_[q], x);
            if (d <= bestDistance) bestDistance = d, best = static_cast<std::ptrdiff_t>(q);
          }
        }
    return best;
  }

 private:
  using Key = std::array<std::int64_t, 3>;
  Key key(const double* x, int i, int j, int k) const {
    return {static_cast<std::int64_t>(std::floor(x[0] / cell_)) + i,
            static_cast<std::int64_t>(std::floor(x[1] / cell_)) + j,
            static_cast<std::int64_t>(std::floor(x[2] / cell_)) + k};
  }
  const Mesh& mesh_;
  const std::vector<std::int64_t>& nodes_;
  double cell_;
  std::map<Key, std::vector<std::size_t>> cells_;
};

// tuples[p][i]: the node of group i matched to node p of the first group.
std::vector<std::vector<std::int64_t>> matchedNodes(const Mesh& mesh, const TieCondition& tie,
                                                    const std::string& what) {
  std::vector<std::vector<std::int64_t>> groups;
  for (const std::string& group : tie.groups) {
    try {
      groups.push_back(mesh.boundaryNodes(group));
    } catch (const std::invalid_argument& e) {
      throw InputError(what + ": " + e.what());
    }
    if (groups.back().empty()) throw InputError(what + ": group '" + group + "' has no nodes");
    if (groups.back().size() != groups.front().size())
      throw InputError(what + ": group '" + group + "' has " +
                       std::to_string(groups.back().size()) + " nodes and '" + tie.groups[0] +
                       "' " + std::to_string(groups.front().size()) +
                       "; tied groups pair their nodes one to one");
  }
  const auto origin = centroid(mesh, groups[0]);
  // Tolerance: of the extent of all the groups' nodes together (the translation included).
  std::vector<std::int64_t> all;
  for (const auto& nodes : groups)
    all.insert(all.end(), nodes.begin(), nodes.end());
  const auto middle = centroid(mesh, all);
  double extent = 0;
  for (auto n : all)
    extent = std::max(extent, distance(mesh, n, middle));
  const double tolerance = kMatchTolerance * extent;
  std::vector<std::vector<std::int64_t>> tuples(groups[0].size());
  for (std::size_t p = 0; p < groups[0].size(); ++p)
    tuples[p].push_back(groups[0][p]);
  for (std::size_t i = 1; i < groups.size(); ++i) {
    const auto c = centroid(mesh, groups[i]);
    const NodeGrid grid(mesh, groups[i], extent, tolerance);
    std::vector<char> used(groups[i].size(), 0);
    for (std::size_t p = 0; p < groups[0].size(); ++p) {
      std::array<double, 3> target;
      for (int k = 0; k < 3; ++k)
        target[k] = mesh.coords[3 * groups[0][p] + k] + c[k] - origin[k];
      // One node a group: the tuple whatever the distance.
      const std::ptrdiff_t q = groups[0].size() == 1 ? 0 : grid.nearest(target, tolerance);
      if (q < 0 || used[q])
        throw InputError(what + ": node " + std::to_string(mesh.nodeId(groups[0][p])) +
                         " of group '" + tie.groups[0] + "' has no partner in group '" +
                         tie.groups[i] +
                         "' at the translation between the groups' centroids; tied groups "
                         "of several nodes must be translates of one another");
      used[q] = 1;
      tuples[p].push_back(groups[i][q]);
    }
  }
  return tuples;
}

// Gauss-Jordan elimination over the equations, one at a time. Each dependent dof p is kept as
// its expression in independent dofs and as the combination of the original equations whose
// reduced row (1 at p, minus the expression) it is: the multipliers of the equations follow from
// the residual at the dependents through those combinations (TiedDof::equations).
class GaussJordan {
 public:
  // One equation; one that makes no dof dependent goes to `redundant` (if given).
  void add(const TieEquation& equation, int index, const std::set<MeshDof>& fixed,
           std::vector<RedundantEquation>* redundant) {
    // The equation with the dependents found so far substituted, and its combination.
    Row row;
    Combination combination{{index, 1.0}};
    for (std::size_t i = 0; i < equation.dofs.size(); ++i) {
      const auto found = dependent_.find(equation.dofs[i]);
      if (found == dependent_.end()) {
        accumulate(row, {{equation.dofs[i], equation.coefficients[i]}}, 1.0);
      } else {
        accumulate(row, found->second, equation.coefficients[i]);
        accumulate(combination, combination_[found->first], -equation.coefficients[i]);
      }
    }
    double largest = 0;
    for (const auto& term : row)
      largest = std::max(largest, std::abs(term.second));
    row.erase(std::remove_if(
                  row.begin(), row.end(),
                  [&](const auto& e) { return std::abs(e.second) <= kDropTolerance * largest; }),
              row.end());
    std::size_t pivot = row.size();
    for (std::size_t i = 0; i < row.size(); ++i)
      if (!fixed.count(row[i].first) &&
          (pivot == row.size() || std::abs(row[i].second) > std::abs(row[pivot].second)))
        pivot = i;
    if (pivot == row.size()) {  // prescribed, or implied by the earlier equations
      if (redundant) redundant->push_back({index, combination});
      return;
    }
    const MeshDof p = row[pivot].first;
    const double a = row[pivot].second;
    Row expression;
    for (std::size_t i = 0; i < row.size(); ++i)
      if (i != pivot) expression.push_back({row[i].first, -row[i].second / a});
    for (auto& term : combination)
      term.second /= a;
    substitute(p, expression, combination);
    for (const auto& term : expression)
      users_[term.first].insert(p);
    dependent_[p] = expression;
    combination_[p] = combination;
    order_.push_back(p);
  }

  std::vector<TiedDof> dependents() const {
    std::vector<TiedDof> out;
    for (const MeshDof& d : order_) {
      TiedDof tied{d, {}, {}};
      for (const auto& term : dependent_.at(d))
        if (term.second != 0) tied.terms.push_back(term);
      for (const auto& term : combination_.at(d))
        if (term.second != 0) tied.equations.push_back(term);
      out.push_back(tied);
    }
    return out;
  }

 private:
  using Row = std::vector<std::pair<MeshDof, double>>;
  using Combination = std::vector<std::pair<int, double>>;

  // row += scale * terms, merging repeated keys.
  template <class Key>
  static void accumulate(std::vector<std::pair<Key, double>>& row,
                         const std::vector<std::pair<Key, double>>& terms, double scale) {
    for (const auto& [key, c] : terms) {
      auto it = std::find_if(row.begin(), row.end(), [&](const auto& e) { return e.first == key; });
      if (it == row.end())
        row.push_back({key, scale * c});
      else
        it->second += scale * c;
    }
  }

  // The earlier dependents that use p (d = ... + c p) now use its expression.
  void substitute(const MeshDof& p, const Row& expression, const Combination& combination) {
    const auto users = users_.find(p);
    if (users == users_.end()) return;
    for (const MeshDof& d : users->second) {
      Row& r = dependent_[d];
      const auto at = std::find_if(r.begin(), r.end(), [&](const auto& e) { return e.first == p; });
      const double c = at->second;
      r.erase(at);
      accumulate(r, expression, c);
      accumulate(combination_[d], combination, c);
      for (const auto& term : expression)
        users_[term.first].insert(d);
    }
    users_.erase(users);
  }

  std::map<MeshDof, Row> dependent_;            // each in independent dofs
  std::map<MeshDof, Combination> combination_;  // each reduced row's original equations
  std::map<MeshDof, std::set<MeshDof>> users_;  // independent dof -> dependents using it
  std::vector<MeshDof> order_;                  // dependents in the order found
};

}  // namespace

std::vector<TieEquation> tieEquations(const SolidModel& model) {
  std::vector<TieEquation> equations;
  for (std::size_t t = 0; t < model.ties.size(); ++t) {
    const TieCondition& tie = model.ties[t];
    const std::string what = "tie '" + tie.name + "'";
    if (tie.groups.size() < 2) throw InputError(what + ": give two groups or more in Groups");
    if (tie.coefficients.size() != tie.groups.size())
      throw InputError(what + ": " + std::to_string(tie.coefficients.size()) +
                       " coefficients for " + std::to_string(tie.groups.size()) +
                       " groups; give one per group");
    for (double a : tie.coefficients)
      if (!std::isfinite(a)) throw InputError(what + ": the coefficients must be finite");
    if (std::all_of(tie.coefficients.begin(), tie.coefficients.end(),
                    [](double a) { return a == 0; }))
      throw InputError(what + ": every coefficient is zero");
    for (const auto& tuple : matchedNodes(*model.mesh, tie, what)) {
      for (std::size_t i = 0; i < tuple.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
          if (tuple[i] == tuple[j])
            throw InputError(what + ": node " + std::to_string(model.mesh->nodeId(tuple[i])) +
                             " is in groups '" + tie.groups[j] + "' and '" + tie.groups[i] +
                             "', which would tie it to itself");
      for (int c : tie.components) {
        TieEquation equation;
        equation.tie = static_cast<int>(t);
        for (std::size_t i = 0; i < tuple.size(); ++i) {
          if (tie.coefficients[i] == 0) continue;
          equation.dofs.push_back({tuple[i], c});
          equation.coefficients.push_back(tie.coefficients[i]);
        }
        equations.push_back(equation);
      }
    }
  }
  return equations;
}

std::vector<std::vector<std::int64_t>> linkedNodes(const std::vector<TieEquation>& equations) {
  std::map<std::int64_t, std::int64_t> parent;  // union-find over the tied nodes
  const auto root = [&](std::int64_t n) {
    while (parent.at(n) != n)
      n = parent[n] = parent[parent[n]];
    return n;
  };
  for (const TieEquation& e : equations)
    for (const MeshDof& d : e.dofs)
      parent.emplace(d.first, d.first);
  for (const TieEquation& e : equations)
    for (const MeshDof& d : e.dofs) {
      const auto a = root(e.dofs.front().first), b = root(d.first);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  std::map<std::int64_t, std::vector<std::int64_t>> sets;
  for (const auto& entry : parent)
    sets[root(entry.first)].push_back(entry.first);  // ascending: parent is ordered
  std::vector<std::vector<std::int64_t>> out;
  for (auto& entry : sets)
    out.push_back(std::move(entry.second));
  return out;
}

std::vector<TiedDof> eliminateTies(const std::vector<TieEquation>& equations,
                                   const std::set<MeshDof>& fixed,
                                   std::vector<RedundantEquation>* redundant) {
  GaussJordan elimination;
  for (std::size_t e = 0; e < equations.size(); ++e)
    elimination.add(equations[e], static_cast<int>(e), fixed, redundant);
  return elimination.dependents();
}

}  // namespace contactlab
