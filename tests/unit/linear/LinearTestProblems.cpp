#include "LinearTestProblems.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Import.hpp>

#include <algorithm>
#include <cmath>

namespace contactlab::test {

std::string nameOf(Layout layout) {
  return layout == Layout::contiguous ? "contiguous" : "scattered";
}

Teuchos::RCP<const Map> makeMap(GO n, Layout layout, const Teuchos::RCP<const Comm>& comm) {
  if (layout == Layout::contiguous) return Teuchos::rcp(new Map(n, 0, comm));
  const int size = comm->getSize(), rank = comm->getRank();
  std::vector<GO> mine;
  for (GO g = n - 1; g >= 0; --g)
    if (g % size == rank) mine.push_back(g);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  return Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GO>(mine), 0, comm));
}

Teuchos::RCP<Matrix> makeMatrix(GO n, Layout layout, const Teuchos::RCP<const Comm>& comm,
                                const RowFunction& rowOf) {
  const auto map = makeMap(n, layout, comm);
  const auto mine = map->getNodeElementList();
  const size_t count = mine.size();
  std::vector<std::vector<GO>> cols(count);
  std::vector<std::vector<double>> vals(count);
  Teuchos::Array<size_t> counts(count);
  for (size_t l = 0; l < count; ++l) {
    rowOf(mine[l], cols[l], vals[l]);
    counts[l] = cols[l].size();
  }
  auto A = Teuchos::rcp(new Matrix(map, counts()));
  for (size_t l = 0; l < count; ++l)
    A->insertGlobalValues(mine[l], Teuchos::ArrayView<const GO>(cols[l]),
                          Teuchos::ArrayView<const double>(vals[l]));
  A->fillComplete();
  return A;
}

Teuchos::RCP<Matrix> modifiedCopy(const Matrix& A, Layout layout, const RowFunction& change) {
  return makeMatrix(static_cast<GO>(A.getGlobalNumRows()), layout, A.getComm(),
                    [&](GO row, std::vector<GO>& cols, std::vector<double>& vals) {
                      Matrix::local_inds_host_view_type indices;
                      Matrix::values_host_view_type values;
                      A.getLocalRowView(A.getRowMap()->getLocalElement(row), indices, values);
                      for (size_t k = 0; k < indices.extent(0); ++k) {
                        cols.push_back(A.getColMap()->getGlobalElement(indices(k)));
                        vals.push_back(values(k));
                      }
                      change(row, cols, vals);
                    });
}

Teuchos::RCP<MultiVector> solved(LinearSolver& solver, const Teuchos::RCP<Matrix>& A,
                                 const MultiVector& b) {
  solver.setMatrix(A, false);
  auto x = Teuchos::rcp(new MultiVector(A->getDomainMap(), b.getNumVectors()));
  solver.solve(b, *x);
  return x;
}

namespace {

// Adds the 5-point stencil of row g = i + nx*j.
void addLaplacian2D(GO g, int nx, int ny, std::vector<GO>& cols, std::vector<double>& vals) {
  const int i = static_cast<int>(g % nx), j = static_cast<int>(g / nx);
  cols.push_back(g);
  vals.push_back(4.0);
  if (i > 0) cols.push_back(g - 1), vals.push_back(-1.0);
  if (i + 1 < nx) cols.push_back(g + 1), vals.push_back(-1.0);
  if (j > 0) cols.push_back(g - nx), vals.push_back(-1.0);
  if (j + 1 < ny) cols.push_back(g + nx), vals.push_back(-1.0);
}

}  // namespace

Teuchos::RCP<Matrix> laplacian2D(int nx, int ny, Layout layout,
                                 const Teuchos::RCP<const Comm>& comm) {
  return makeMatrix(GO(nx) * ny, layout, comm,
                    [&](GO g, auto& cols, auto& vals) { addLaplacian2D(g, nx, ny, cols, vals); });
}

Teuchos::RCP<Matrix> laplacian3D(int n, Layout layout, const Teuchos::RCP<const Comm>& comm) {
  const GO n2 = GO(n) * n;
  return makeMatrix(n2 * n, layout, comm, [&](GO g, auto& cols, auto& vals) {
    const GO i = g % n, j = (g / n) % n, k = g / n2;
    cols.push_back(g);
    vals.push_back(6.0);
    const GO steps[3] = {1, n, n2};
    const GO coords[3] = {i, j, k};
    for (int d = 0; d < 3; ++d) {
      if (coords[d] > 0) cols.push_back(g - steps[d]), vals.push_back(-1.0);
      if (coords[d] + 1 < n) cols.push_back(g + steps[d]), vals.push_back(-1.0);
    }
  });
}

Teuchos::RCP<Matrix> saddlePoint(int nx, int m, Layout layout,
                                 const Teuchos::RCP<const Comm>& comm) {
  const GO n = GO(nx) * nx;
  const GO spacing = n / m;  // constraint c ties unknowns c*spacing and c*spacing + 1
  return makeMatrix(n + m, layout, comm, [&](GO g, auto& cols, auto& vals) {
    if (g < n) {
      addLaplacian2D(g, nx, nx, cols, vals);
      if (g % spacing <= 1 && g / spacing < m) {  // column of B^T
        cols.push_back(n + g / spacing);
        vals.push_back(g % spacing == 0 ? 1.0 : -1.0);
      }
    } else {
      const GO c = g - n;
      cols.push_back(c * spacing), vals.push_back(1.0);
      cols.push_back(c * spacing + 1), vals.push_back(-1.0);
      cols.push_back(g), vals.push_back(0.0);  // a stored zero diagonal, as assembly gives
    }
  });
}

Teuchos::RCP<Matrix> convectionDiffusion(int nx, double a, Layout layout,
                                         const Teuchos::RCP<const Comm>& comm) {
  return makeMatrix(GO(nx) * nx, layout, comm, [&](GO g, auto& cols, auto& vals) {
    const int i = static_cast<int>(g % nx), j = static_cast<int>(g / nx);
    cols.push_back(g), vals.push_back(4.0 + 2 * a);
    if (i > 0) cols.push_back(g - 1), vals.push_back(-1.0 - a);
    if (i + 1 < nx) cols.push_back(g + 1), vals.push_back(-1.0);
    if (j > 0) cols.push_back(g - nx), vals.push_back(-1.0 - a);
    if (j + 1 < nx) cols.push_back(g + nx), vals.push_back(-1.0);
  });
}

Teuchos::RCP<Matrix> tinyDiagonalIndefinite(int nx, Layout layout,
                                            const Teuchos::RCP<const Comm>& comm) {
  // Off-diagonal (g, h) depends on min(g, h) only: symmetric.
  const auto horizontal = [](GO g) { return 1.0 + 0.1 * ((g * 13) % 5); };
  const auto vertical = [](GO g) { return -1.0 - 0.01 * (g % 3); };
  return makeMatrix(GO(nx) * nx, layout, comm, [&](GO g, auto& cols, auto& vals) {
    const int i = static_cast<int>(g % nx), j = static_cast<int>(g / nx);
    cols.push_back(g), vals.push_back(1e-10 * ((g % 7) - 3));
    if (i > 0) cols.push_back(g - 1), vals.push_back(horizontal(g - 1));
    if (i + 1 < nx) cols.push_back(g + 1), vals.push_back(horizontal(g));
    if (j > 0) cols.push_back(g - nx), vals.push_back(vertical(g - nx));
    if (j + 1 < nx) cols.push_back(g + nx), vals.push_back(vertical(g));
  });
}

Teuchos::RCP<Matrix> tridiagonal(GO n, Layout layout, const Teuchos::RCP<const Comm>& comm) {
  return makeMatrix(n, layout, comm, [&](GO g, auto& cols, auto& vals) {
    cols.push_back(g), vals.push_back(2.0);
    if (g > 0) cols.push_back(g - 1), vals.push_back(-1.0);
    if (g + 1 < n) cols.push_back(g + 1), vals.push_back(-1.0);
  });
}

Teuchos::RCP<Matrix> diagonal(GO n, const std::function<double(GO)>& d, Layout layout,
                              const Teuchos::RCP<const Comm>& comm) {
  return makeMatrix(n, layout, comm,
                    [&](GO g, auto& cols, auto& vals) { cols.push_back(g), vals.push_back(d(g)); });
}

Teuchos::RCP<MultiVector> rightHandSide(const Matrix& A, size_t columns) {
  auto b = Teuchos::rcp(new MultiVector(A.getRangeMap(), columns));
  const auto map = A.getRangeMap();
  for (size_t j = 0; j < columns; ++j) {
    auto data = b->getDataNonConst(j);
    for (size_t l = 0; l < map->getNodeNumElements(); ++l) {
      const double g = static_cast<double>(map->getGlobalElement(static_cast<LO>(l)));
      data[l] = std::sin(0.37 * g + 1.0 + j) + 0.1 * (j + 1);
    }
  }
  return b;
}

std::vector<double> gathered(const MultiVector& v, size_t col) {
  const auto map = v.getMap();
  const GO n = static_cast<GO>(map->getGlobalNumElements());
  const auto all = Teuchos::rcp(new Map(n, GO(0), map->getComm(), Tpetra::LocallyReplicated));
  Vector copy(all);
  Import importer(map, all);
  copy.doImport(*v.getVector(col), importer, Tpetra::INSERT);
  const auto data = copy.getData();
  std::vector<double> out(n);
  for (GO l = 0; l < n; ++l)
    out[all->getGlobalElement(static_cast<LO>(l))] = data[l];
  return out;
}

double relativeResidual(const Matrix& A, const MultiVector& b, const MultiVector& x) {
  MultiVector r(b, Teuchos::Copy);
  A.apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
  std::vector<double> rn(b.getNumVectors()), bn(b.getNumVectors());
  r.norm2(rn);
  b.norm2(bn);
  double worst = 0;
  for (size_t j = 0; j < rn.size(); ++j)
    worst = std::max(worst, rn[j] / bn[j]);
  return worst;
}

double backwardError(const Matrix& A, const MultiVector& b, const MultiVector& x) {
  MultiVector r(b, Teuchos::Copy);
  A.apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
  const size_t n = b.getNumVectors();
  std::vector<double> rn(n), xn(n), bn(n);
  r.normInf(rn);
  x.normInf(xn);
  b.normInf(bn);
  double localNorm = 0;  // ||A||_inf: the largest absolute row sum
  for (LO row = 0; row < static_cast<LO>(A.getNodeNumRows()); ++row) {
    Matrix::local_inds_host_view_type cols;
    Matrix::values_host_view_type values;
    A.getLocalRowView(row, cols, values);
    double sum = 0;
    for (size_t k = 0; k < values.extent(0); ++k)
      sum += std::abs(values(k));
    localNorm = std::max(localNorm, sum);
  }
  double norm = 0;
  Teuchos::reduceAll(*A.getComm(), Teuchos::REDUCE_MAX, localNorm, Teuchos::outArg(norm));
  double worst = 0;
  for (size_t j = 0; j < n; ++j)
    worst = std::max(worst, rn[j] / (norm * xn[j] + bn[j]));
  return worst;
}

double relativeDifference(const MultiVector& x, const MultiVector& y) {
  double worst = 0;
  for (size_t j = 0; j < y.getNumVectors(); ++j) {
    const auto xs = gathered(x, j), ys = gathered(y, j);
    double d = 0, s = 0;
    for (size_t i = 0; i < ys.size(); ++i) {
      d += (xs[i] - ys[i]) * (xs[i] - ys[i]);
      s += ys[i] * ys[i];
    }
    worst = std::max(worst, std::sqrt(d / s));
  }
  return worst;
}

}  // namespace contactlab::test
