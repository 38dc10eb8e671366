#include "algorithms/PatternCriticalFriction.hpp"

#include "algorithms/CriticalFriction.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace contactlab {

PatternCriticalFriction patternCriticalFriction(NonlinearSystem& system, ContactControls& controls,
                                                LinearSolver& solver, const Vector& x, double t) {
  // The pattern of x: statuses of an evaluation at x, then held.
  system.assemble(x, t, nullptr, false);
  const auto states = controls.pointStates();
  for (std::size_t i = 0; i < states.size(); ++i)
    controls.forceStatus(i, states[i].status);

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

  controls.setFrictionScale(1.0);
  controls.releaseTreatments();
  system.assemble(x, t, nullptr, true);
  return out;
}

}  // namespace contactlab
