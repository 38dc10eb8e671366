#include "algorithms/PatternCriticalFriction.hpp"

#include "algorithms/CriticalFriction.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace contactlab {

PatternCriticalFriction patternCriticalFriction(NonlinearSystem& system, ContactControls& controls,
                                                LinearSolver& solver, const Vector& x, double t,
                                                std::vector<int> statuses) {
  if (statuses.empty()) {  // the pattern of x: statuses of an evaluation at x
    system.assemble(x, t, nullptr, false);
    for (const auto& s : controls.pointStates())
      statuses.push_back(s.status);
  }
  for (std::size_t i = 0; i < statuses.size(); ++i)
    controls.forceStatus(i, statuses[i]);

  auto assembleAt = [&](double scale) {
    controls.setFrictionScale(scale);
    system.assemble(x, t, nullptr, true);
    return Teuchos::rcp(new Matrix(*system.tangent(), Teuchos::Copy));
  };
  const auto J1 = assembleAt(1.0);
  const auto B = assembleAt(2.0);  // becomes J(2) - J(1): the same graph, value by value
  {
    B->resumeFill();
    const auto b = B->getLocalMatrixHost().values;
    const auto j1 = J1->getLocalMatrixHost().values;
    for (std::size_t e = 0; e < b.extent(0); ++e)
      b(e) -= j1(e);
    B->fillComplete(B->getDomainMap(), B->getRangeMap());
  }

  // Rows of B that are not zero (relative to J1's size), numbered globally in GID order.
  const auto map = J1->getRowMap();
  const auto comm = map->getComm();
  double jMax = 0, jMaxGlobal = 0;
  {
    const auto j1 = J1->getLocalMatrixHost().values;
    for (std::size_t e = 0; e < j1.extent(0); ++e)
      jMax = std::max(jMax, std::abs(j1(e)));
  }
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 1, &jMax, &jMaxGlobal);
  const GO n = static_cast<GO>(map->getGlobalNumElements());
  std::vector<int> flag(static_cast<std::size_t>(n), 0), flagGlobal(flag.size(), 0);
  {
    const auto local = B->getLocalMatrixHost();
    for (LO r = 0; r < static_cast<LO>(map->getNodeNumElements()); ++r)
      for (auto e = local.graph.row_map(r); e < local.graph.row_map(r + 1); ++e)
        if (std::abs(local.values(e)) > 1e-13 * jMaxGlobal) flag[map->getGlobalElement(r)] = 1;
  }
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, static_cast<int>(n), flag.data(),
                     flagGlobal.data());
  std::vector<GO> rows;
  for (GO g = 0; g < n; ++g)
    if (flagGlobal[g]) rows.push_back(g);
  const int k = static_cast<int>(rows.size());

  PatternCriticalFriction out;
  out.frictionRows = k;
  // Restores the system whatever happens next (a singular J(1) throws from the solver).
  struct Restore {
    NonlinearSystem& system;
    ContactControls& controls;
    const Vector& x;
    double t;
    ~Restore() {
      controls.setFrictionScale(1.0);
      controls.releaseTreatments();
      system.assemble(x, t, nullptr, true);
    }
  } restore{system, controls, x, t};
  solver.setMatrix(J1, true);
  out.determinant = solver.determinant();
  if (k == 0) {
    out.scale = std::numeric_limits<double>::infinity();
  } else {
    MultiVector E(map, static_cast<std::size_t>(k)), X(map, static_cast<std::size_t>(k)),
        Y(map, static_cast<std::size_t>(k));
    for (int j = 0; j < k; ++j)
      if (map->isNodeGlobalElement(rows[j]))
        E.replaceGlobalValue(rows[j], static_cast<std::size_t>(j), 1.0);
    solver.solve(E, X);
    B->apply(X, Y);
    // M = B_R X (k x k, column major), summed over the ranks owning the rows.
    std::vector<double> M(static_cast<std::size_t>(k) * k, 0.0), MGlobal(M.size(), 0.0);
    for (int j = 0; j < k; ++j) {
      const auto y = Y.getData(static_cast<std::size_t>(j));
      for (int i = 0; i < k; ++i) {
        const LO lid = map->getLocalElement(rows[i]);
        if (lid != Teuchos::OrdinalTraits<LO>::invalid())
          M[static_cast<std::size_t>(j) * k + i] = y[lid];
      }
    }
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, static_cast<int>(M.size()), M.data(),
                       MGlobal.data());
    // det(I + (s - 1) M) = det((I - M) + s M).
    std::vector<double> A(MGlobal.size());
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < k; ++i) {
        const std::size_t e = static_cast<std::size_t>(j) * k + i;
        A[e] = (i == j ? 1.0 : 0.0) - MGlobal[e];
      }
    // Roots at s ~ 0 come from the multipliers' scaling by the threshold (CriticalFriction.hpp).
    const CriticalFriction c = criticalFriction(k, A, MGlobal, 1e-8);
    out.scale = c.mu;
    out.realRoots = c.realRoots;
  }
  return out;
}

UniquenessCheck checkUniqueness(NonlinearSystem& system, ContactControls& controls,
                                LinearSolver& solver, const Vector& x, double t, double tolerance,
                                int maxPatterns) {
  system.assemble(x, t, nullptr, false);
  const auto states = controls.pointStates();
  std::vector<int> base;
  double largest = 0;
  for (const auto& s : states) {
    base.push_back(s.status);
    if (s.zone != 0) largest = std::max(largest, std::abs(s.contactIndicator));
  }
  // Adjacent statuses of each ambiguous point (its own first).
  std::vector<std::size_t> points;
  std::vector<std::vector<int>> choices;
  for (std::size_t i = 0; i < states.size(); ++i) {
    const auto& s = states[i];
    if (s.zone == 0) continue;
    std::vector<int> alt{s.status};
    auto add = [&](int status) {
      if (std::find(alt.begin(), alt.end(), status) == alt.end()) alt.push_back(status);
    };
    const bool friction = s.frictionIndicator != 0.0;
    if (std::abs(s.contactIndicator) <= tolerance * largest) {
      add(0);
      add(friction && s.frictionIndicator > 0 ? 2 : 1);
    }
    if (s.status != 0 && friction && std::abs(s.frictionIndicator) <= tolerance) {
      add(1);
      add(2);
    }
    if (alt.size() > 1) {
      points.push_back(i);
      choices.push_back(alt);
    }
  }
  UniquenessCheck out;
  out.ambiguousPoints = static_cast<int>(points.size());
  std::vector<std::vector<int>> patterns{base};
  double combinations = 1;
  for (const auto& c : choices)
    combinations *= static_cast<double>(c.size());
  if (combinations <= maxPatterns) {
    out.choice = "every combination of the ambiguous points' statuses";
    for (std::size_t p = 0; p < points.size(); ++p) {
      std::vector<std::vector<int>> next;
      for (const auto& pattern : patterns)
        for (int status : choices[p]) {
          auto q = pattern;
          q[points[p]] = status;
          next.push_back(q);
        }
      patterns.swap(next);
    }
  } else {
    out.choice = "the converged pattern and single changes of one ambiguous point (" +
                 std::to_string(static_cast<long long>(combinations)) +
                 " combinations are too many), at most " + std::to_string(maxPatterns);
    for (std::size_t p = 0; p < points.size(); ++p)
      for (std::size_t a = 1; a < choices[p].size(); ++a)
        if (static_cast<int>(patterns.size()) < maxPatterns) {
          auto q = base;
          q[points[p]] = choices[p][a];
          patterns.push_back(q);
        }
  }
  out.scale = std::numeric_limits<double>::infinity();
  int firstSign = 0;
  out.signsKnown = true;
  for (const auto& pattern : patterns) {
    ++out.patterns;
    PatternCriticalFriction c;
    try {
      c = patternCriticalFriction(system, controls, solver, x, t, pattern);
    } catch (const LinearSolverError&) {
      ++out.singularPatterns;
      out.sameSign = false;
      continue;
    }
    out.scale = std::min(out.scale, c.scale);
    if (!c.determinant) {
      out.signsKnown = false;
      continue;
    }
    const int sign = c.determinant->sign();
    if (firstSign == 0) firstSign = sign;
    if (sign != firstSign && out.sameSign) {
      out.sameSign = false;
      for (std::size_t p = 0; p < points.size(); ++p)
        out.breakingPattern += (p ? ", " : "") + std::string("point ") + std::to_string(points[p]) +
                               ": " + std::to_string(pattern[points[p]]);
    }
  }
  return out;
}

}  // namespace contactlab
