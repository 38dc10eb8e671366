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
                                   const std::set<MeshDof>& fixed) {
  using Row = std::vector<std::pair<MeshDof, double>>;
  std::map<MeshDof, Row> dependent;                 // each in independent dofs
  std::map<MeshDof, std::set<MeshDof>> dependents;  // independent dof -> dependents using it
  std::vector<MeshDof> order;                       // dependents in the order found
  // row += scale * terms, merging repeated dofs.
  const auto add = [](Row& row, const Row& terms, double scale) {
    for (const auto& [dof, c] : terms) {
      auto it = std::find_if(row.begin(), row.end(), [&](const auto& e) { return e.first == dof; });
      if (it == row.end())
        row.push_back({dof, scale * c});
      else
        it->second += scale * c;
    }
  };
  for (const TieEquation& equation : equations) {
    Row row;
    for (std::size_t i = 0; i < equation.dofs.size(); ++i) {
      const auto found = dependent.find(equation.dofs[i]);
      if (found == dependent.end())
        add(row, {{equation.dofs[i], equation.coefficients[i]}}, 1.0);
      else
        add(row, found->second, equation.coefficients[i]);
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
    if (pivot == row.size()) continue;  // prescribed, or implied by the earlier equations
    const MeshDof p = row[pivot].first;
    Row expression;
    for (std::size_t i = 0; i < row.size(); ++i)
      if (i != pivot) expression.push_back({row[i].first, -row[i].second / row[pivot].second});
    // Earlier dependents that use p now use its expression.
    const auto users = dependents.find(p);
    if (users != dependents.end()) {
      for (const MeshDof& d : users->second) {
        Row& r = dependent[d];
        const auto at =
            std::find_if(r.begin(), r.end(), [&](const auto& e) { return e.first == p; });
        const double c = at->second;
        r.erase(at);
        add(r, expression, c);
        for (const auto& term : expression)
          dependents[term.first].insert(d);
      }
      dependents.erase(users);
    }
    for (const auto& term : expression)
      dependents[term.first].insert(p);
    dependent[p] = expression;
    order.push_back(p);
  }
  std::vector<TiedDof> out;
  for (const MeshDof& d : order) {
    Row terms;
    for (const auto& term : dependent[d])
      if (term.second != 0) terms.push_back(term);
    out.push_back({d, terms});
  }
  return out;
}

}  // namespace contactlab
