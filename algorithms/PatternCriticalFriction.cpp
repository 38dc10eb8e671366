#include "algorithms/PatternCriticalFriction.hpp"

#include "algorithms/CriticalFriction.hpp"
#include "formulations/BallProjection.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace contactlab {
namespace {

// J(1) and J(2) with `statuses` held (the same graph: their differences are taken value by value).
struct PatternMatrices {
  Teuchos::RCP<Matrix> J1, J2;
};

PatternMatrices assemblePattern(NonlinearSystem& system, ContactControls& controls, const Vector& x,
                                double t, const std::vector<int>& statuses) {
  for (std::size_t i = 0; i < statuses.size(); ++i)
    controls.forceStatus(i, statuses[i]);
  auto assembleAt = [&](double scale) {
    controls.setFrictionScale(scale);
    system.assemble(x, t, nullptr, true);
    return Teuchos::rcp(new Matrix(*system.tangent(), Teuchos::Copy));
  };
  PatternMatrices p;
  p.J1 = assembleAt(1.0);
  p.J2 = assembleAt(2.0);
  controls.setFrictionScale(1.0);
  return p;
}

double largestEntry(const Matrix& A) {
  double local = 0, global = 0;
  const auto a = A.getLocalMatrixHost().values;
  for (std::size_t e = 0; e < a.extent(0); ++e)
    local = std::max(local, std::abs(a(e)));
  Teuchos::reduceAll(*A.getRowMap()->getComm(), Teuchos::REDUCE_MAX, 1, &local, &global);
  return global;
}

// The union over the ranks of each rank's global indices `mine`, ascending, on every rank.
std::vector<GO> onEveryRank(const std::vector<GO>& mine, const Map& map) {
  const GO n = static_cast<GO>(map.getGlobalNumElements());
  std::vector<int> flag(static_cast<std::size_t>(n), 0), flagGlobal(flag.size(), 0);
  for (GO g : mine)
    flag[static_cast<std::size_t>(g)] = 1;
  Teuchos::reduceAll(*map.getComm(), Teuchos::REDUCE_MAX, static_cast<int>(n), flag.data(),
                     flagGlobal.data());
  std::vector<GO> all;
  for (GO g = 0; g < n; ++g)
    if (flagGlobal[g]) all.push_back(g);
  return all;
}

// The identity's columns at `rows`.
MultiVector unitColumns(const Teuchos::RCP<const Map>& map, const std::vector<GO>& rows) {
  MultiVector E(map, rows.size());
  for (std::size_t j = 0; j < rows.size(); ++j)
    if (map->isNodeGlobalElement(rows[j])) E.replaceGlobalValue(rows[j], j, 1.0);
  return E;
}

// Y's entries at `rows` (all columns), rows.size() x Y's columns, column major, on every rank.
std::vector<double> gatherRows(const MultiVector& Y, const std::vector<GO>& rows) {
  const auto map = Y.getMap();
  const std::size_t m = rows.size(), c = Y.getNumVectors();
  std::vector<double> local(m * c, 0.0), global(local.size(), 0.0);
  for (std::size_t j = 0; j < c; ++j) {
    const auto y = Y.getData(j);
    for (std::size_t i = 0; i < m; ++i) {
      const LO lid = map->getLocalElement(rows[i]);
      if (lid != Teuchos::OrdinalTraits<LO>::invalid()) local[j * m + i] = y[lid];
    }
  }
  if (!local.empty())
    Teuchos::reduceAll(*map->getComm(), Teuchos::REDUCE_SUM, static_cast<int>(local.size()),
                       local.data(), global.data());
  return global;
}

// The locally owned rows of A - B (same graph, value by value) that have entries above
// `threshold`, with those entries (global columns): B = J(2) - J(1) and J'(1) - J(1) have a few
// such rows, and products with them should cost those. `all`: their rows on every rank.
struct SparseRows {
  std::vector<GO> rows, all;
  std::vector<std::vector<std::pair<GO, double>>> entries;
};

SparseRows sparseDifference(const Matrix& A, const Matrix& B, double threshold) {
  const auto rowMap = A.getRowMap();
  const auto colMap = A.getColMap();
  const auto a = A.getLocalMatrixHost();
  const auto b = B.getLocalMatrixHost().values;
  SparseRows s;
  for (LO r = 0; r < static_cast<LO>(rowMap->getNodeNumElements()); ++r) {
    std::vector<std::pair<GO, double>> row;
    for (auto e = a.graph.row_map(r); e < a.graph.row_map(r + 1); ++e)
      if (std::abs(a.values(e) - b(e)) > threshold)
        row.emplace_back(colMap->getGlobalElement(a.graph.entries(e)), a.values(e) - b(e));
    if (row.empty()) continue;
    s.rows.push_back(rowMap->getGlobalElement(r));
    s.entries.push_back(std::move(row));
  }
  s.all = onEveryRank(s.rows, *rowMap);
  return s;
}

// The columns that `a` and `b` touch on any rank, ascending, on every rank.
std::vector<GO> columnsOf(const SparseRows& a, const SparseRows& b, const Map& map) {
  std::vector<GO> mine;
  for (const SparseRows* s : {&a, &b})
    for (const auto& row : s->entries)
      for (const auto& entry : row)
        mine.push_back(entry.first);
  return onEveryRank(mine, map);
}

// (A V) at `rows` (A's nonzero rows among them), rows.size() x c, column major, on every rank;
// V is given at the rows `columns` (columns.size() x c, the same on every rank).
std::vector<double> product(const SparseRows& A, const std::vector<GO>& rows,
                            const std::vector<GO>& columns, const std::vector<double>& V,
                            std::size_t c, const Comm& comm) {
  const std::size_t m = rows.size(), nc = columns.size();
  std::vector<double> local(m * c, 0.0), global(local.size(), 0.0);
  for (std::size_t a = 0; a < A.rows.size(); ++a) {
    const std::size_t i = static_cast<std::size_t>(
        std::lower_bound(rows.begin(), rows.end(), A.rows[a]) - rows.begin());
    for (const auto& [column, value] : A.entries[a]) {
      const std::size_t l = static_cast<std::size_t>(
          std::lower_bound(columns.begin(), columns.end(), column) - columns.begin());
      for (std::size_t j = 0; j < c; ++j)
        local[j * m + i] += value * V[j * nc + l];
    }
  }
  if (!local.empty())
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(),
                       global.data());
  return global;
}

// The pattern's critical factor from M = B_R J(1)^-1 E_R (k x k): det J(s) = det J(1)
// det(I + (s - 1) M) = det J(1) det((I - M) + s M).
CriticalFriction reducedCriticalFriction(int k, const std::vector<double>& M) {
  if (k == 0) {
    CriticalFriction none;
    none.mu = std::numeric_limits<double>::infinity();
    return none;
  }
  // Roots at s ~ 0 come from the multipliers' scaling by the threshold (CriticalFriction.hpp).
  return criticalFactorOfUpdate(k, M, 1e-8);
}

// Restores the system whatever happens (a singular J(1) throws from the solver).
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
};

// A pattern factorized with the solver: J(1), B's nonzero rows R = B.all (they depend on mu) and
// X = J(1)^-1 E_R, so that patterns differing from it in a few rows cost a few more solves.
struct FactorizedPattern {
  Teuchos::RCP<Matrix> J1;
  SparseRows B;
  Teuchos::RCP<MultiVector> X;
  std::optional<Determinant> determinant;
  double threshold = 0;  // entries below it are zero (relative to J(1)'s largest)
};

FactorizedPattern factorize(const PatternMatrices& matrices, LinearSolver& solver) {
  FactorizedPattern f;
  f.J1 = matrices.J1;
  f.threshold = 1e-13 * largestEntry(*f.J1);
  f.B = sparseDifference(*matrices.J2, *f.J1, f.threshold);
  solver.setMatrix(f.J1, true);
  f.determinant = solver.determinant();
  const auto map = f.J1->getRowMap();
  f.X = Teuchos::rcp(new MultiVector(map, std::max<std::size_t>(f.B.all.size(), 1)));
  if (!f.B.all.empty()) solver.solve(unitColumns(map, f.B.all), *f.X);
  return f;
}

PatternCriticalFriction criticalOf(const FactorizedPattern& f) {
  PatternCriticalFriction out;
  const std::size_t k = f.B.all.size();
  out.frictionRows = static_cast<int>(k);
  out.determinant = f.determinant;
  const auto map = f.J1->getRowMap();
  const std::vector<GO> S = columnsOf(f.B, SparseRows{}, *map);
  const CriticalFriction c = reducedCriticalFriction(
      static_cast<int>(k), k ? product(f.B, f.B.all, S, gatherRows(*f.X, S), k, *map->getComm())
                             : std::vector<double>{});
  out.scale = c.mu;
  out.realRoots = c.realRoots;
  return out;
}

// A pattern whose J(1) differs from the factorized one's in the rows Q only: J'(1) = J(1) +
// E_Q D_Q, so by the Sherman-Morrison-Woodbury formula J'(1)^-1 E_R' = W - Z K^-1 D_Q W, with
// W = J(1)^-1 E_R', Z = J(1)^-1 E_Q and K = I + D_Q Z (q x q), det J'(1) = det J(1) det K and
// M' = B'_R' W - (B'_R' Z) K^-1 (D_Q W). The rows R' that depend on mu are rows of R or of Q,
// so W's columns are X's or Z's, and only their entries where D_Q and B' have entries are
// needed: q solves and dense algebra of size k in place of a factorization and k solves.
// Empty when Q has more than `maxRows` rows (a factorization is then the cheaper way).
std::optional<PatternCriticalFriction> updatedCritical(const FactorizedPattern& base,
                                                       const PatternMatrices& p,
                                                       LinearSolver& solver, std::size_t maxRows) {
  const auto map = base.J1->getRowMap();
  const Comm& comm = *map->getComm();
  const SparseRows D = sparseDifference(*p.J1, *base.J1, base.threshold);  // J'(1) - J(1)
  const std::vector<GO>& Q = D.all;
  if (Q.size() > maxRows) return std::nullopt;
  const SparseRows B = sparseDifference(*p.J2, *p.J1, base.threshold);
  const std::vector<GO>& R = B.all;
  const std::vector<GO> S = columnsOf(D, B, *map);
  const std::size_t q = Q.size(), k = R.size(), ns = S.size();

  PatternCriticalFriction out;
  out.frictionRows = static_cast<int>(k);
  out.determinant = base.determinant;
  std::vector<double> ZS;  // Z at the rows S
  std::vector<double> K;   // I + D_Q Z, LU factors
  std::vector<int> pivots(std::max<std::size_t>(q, 1));
  Teuchos::LAPACK<int, double> lapack;
  if (q > 0) {
    MultiVector Z(map, q);
    solver.solve(unitColumns(map, Q), Z);
    ZS = gatherRows(Z, S);
    K = product(D, Q, S, ZS, q, comm);
    for (std::size_t i = 0; i < q; ++i)
      K[i * q + i] += 1.0;
    const Determinant dK = denseDeterminant(static_cast<int>(q), K);
    if (dK.sign() == 0) throw LinearSolverError("J(1) of the pattern is singular");
    if (base.determinant)
      out.determinant = Determinant::normalized(base.determinant->mantissa * dK.mantissa,
                                                base.determinant->exponent + dK.exponent);
    int info = 0;
    lapack.GETRF(static_cast<int>(q), static_cast<int>(q), K.data(), static_cast<int>(q),
                 pivots.data(), &info);
  }
  if (k == 0) {
    out.scale = std::numeric_limits<double>::infinity();
    return out;
  }
  // W at the rows S, column by column from X or Z.
  auto position = [](const std::vector<GO>& rows, GO g) -> std::optional<std::size_t> {
    const auto it = std::lower_bound(rows.begin(), rows.end(), g);
    if (it == rows.end() || *it != g) return std::nullopt;
    return static_cast<std::size_t>(it - rows.begin());
  };
  const std::vector<double> XS = gatherRows(*base.X, S);
  std::vector<double> WS(ns * k);
  for (std::size_t j = 0; j < k; ++j) {
    const double* source = nullptr;
    if (const auto inX = position(base.B.all, R[j]))
      source = &XS[*inX * ns];
    else if (const auto inZ = position(Q, R[j]))
      source = &ZS[*inZ * ns];
    else
      return std::nullopt;  // a row whose mu-dependence alone changed: not covered by X and Z
    std::copy(source, source + ns, &WS[j * ns]);
  }
  std::vector<double> M = product(B, R, S, WS, k, comm);  // B'_R' W
  if (q > 0) {                                            // - (B'_R' Z) K^-1 (D_Q W)
    std::vector<double> H = product(D, Q, S, WS, k, comm);
    int info = 0;
    lapack.GETRS('N', static_cast<int>(q), static_cast<int>(k), K.data(), static_cast<int>(q),
                 pivots.data(), H.data(), static_cast<int>(q), &info);
    const std::vector<double> BZ = product(B, R, S, ZS, q, comm);
    for (std::size_t j = 0; j < k; ++j)
      for (std::size_t l = 0; l < q; ++l)
        for (std::size_t i = 0; i < k; ++i)
          M[j * k + i] -= BZ[l * k + i] * H[j * q + l];
  }
  const CriticalFriction c = reducedCriticalFriction(static_cast<int>(k), M);
  out.scale = c.mu;
  out.realRoots = c.realRoots;
  return out;
}

}  // namespace

PatternCriticalFriction patternCriticalFriction(NonlinearSystem& system, ContactControls& controls,
                                                LinearSolver& solver, const Vector& x, double t,
                                                std::vector<int> statuses) {
  if (statuses.empty()) {  // the pattern of x: statuses of an evaluation at x
    system.assemble(x, t, nullptr, false);
    for (const auto& s : controls.pointStates())
      statuses.push_back(s.status);
  }
  Restore restore{system, controls, x, t};
  return criticalOf(factorize(assemblePattern(system, controls, x, t, statuses), solver));
}

UniquenessCheck checkUniqueness(NonlinearSystem& system, ContactControls& controls,
                                LinearSolver& solver, const Vector& x, double t, double tolerance,
                                int maxPatterns, int maxUpdateRows) {
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
    std::ostringstream many;
    many << std::setprecision(3) << combinations;
    out.choice = "the converged pattern and single changes of one ambiguous point (" + many.str() +
                 " combinations are too many), at most " + std::to_string(maxPatterns);
    for (std::size_t p = 0; p < points.size(); ++p)
      for (std::size_t a = 1; a < choices[p].size(); ++a)
        if (static_cast<int>(patterns.size()) < maxPatterns) {
          auto q = base;
          q[points[p]] = choices[p][a];
          patterns.push_back(q);
        }
  }

  Restore restore{system, controls, x, t};
  // The converged pattern first, factorized; the others by updates of it when they differ from
  // it in at most maxUpdateRows rows of J(1), by their own factorization otherwise.
  std::optional<FactorizedPattern> converged;
  bool convergedInSolver = false;
  auto examine = [&](const std::vector<int>& pattern) -> PatternCriticalFriction {
    const PatternMatrices m = assemblePattern(system, controls, x, t, pattern);
    if (!converged) {
      converged = factorize(m, solver);
      convergedInSolver = true;
      return criticalOf(*converged);
    }
    if (maxUpdateRows > 0) {
      if (!convergedInSolver) {
        solver.setMatrix(converged->J1, false);
        convergedInSolver = true;
      }
      if (auto c =
              updatedCritical(*converged, m, solver, static_cast<std::size_t>(maxUpdateRows))) {
        ++out.updatedPatterns;
        return *c;
      }
    }
    convergedInSolver = false;
    return criticalOf(factorize(m, solver));
  };

  out.localScale = std::numeric_limits<double>::infinity();
  int firstSign = 0;
  out.signsKnown = true;
  for (const auto& pattern : patterns) {
    ++out.patterns;
    PatternCriticalFriction c;
    try {
      c = examine(pattern);
    } catch (const LinearSolverError&) {
      ++out.singularPatterns;
      out.sameSign = false;
      continue;
    }
    out.localScale = std::min(out.localScale, c.scale);
    out.frictionRows = std::max(out.frictionRows, c.frictionRows);
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
  // Every closed point slipping as at its onset (|Lambda^| on the ball: the Jacobian a sticking
  // point takes as it starts to slip), in the direction of its traction. It differs from the
  // converged pattern in every sticking point's rows: its own factorization.
  std::vector<int> slipping = base;
  for (int& s : slipping)
    if (s != 0) s = kSlipOnset;
  out.slipScale = std::numeric_limits<double>::infinity();
  if (std::any_of(slipping.begin(), slipping.end(), [](int s) { return s != 0; })) {
    try {
      const PatternCriticalFriction c =
          criticalOf(factorize(assemblePattern(system, controls, x, t, slipping), solver));
      out.slipScale = c.scale;
      out.frictionRows = std::max(out.frictionRows, c.frictionRows);
    } catch (const LinearSolverError&) {
      out.slipScale = 1.0;  // det J(1) = 0: a root at the model's mu (a smaller one may exist)
    }
  }
  out.scale = std::min(out.localScale, out.slipScale);
  return out;
}

}  // namespace contactlab
