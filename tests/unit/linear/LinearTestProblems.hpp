#pragma once
// Test matrices for the linear solvers, built on any number of ranks with either a contiguous
// row map or a scattered one (rows dealt round-robin to the ranks and listed in decreasing order,
// so the map is non-contiguous even on one rank). The matrix entry (i, j) is the same whatever
// the layout: solutions compare by global id.
#include "base/LinearAlgebra.hpp"
#include "linear/LinearSolver.hpp"

#include <Teuchos_RCP.hpp>

#include <functional>
#include <string>
#include <vector>

namespace contactlab::test {

enum class Layout { contiguous, scattered };
std::string nameOf(Layout layout);

Teuchos::RCP<const Map> makeMap(GO n, Layout layout, const Teuchos::RCP<const Comm>& comm);

// Fills the columns and values of global row `row`.
using RowFunction = std::function<void(GO row, std::vector<GO>& cols, std::vector<double>& vals)>;
Teuchos::RCP<Matrix> makeMatrix(GO n, Layout layout, const Teuchos::RCP<const Comm>& comm,
                                const RowFunction& rowOf);
// A copy of A (built with `layout`), each global row's columns and values then handed to
// `change`, which may alter or add entries.
Teuchos::RCP<Matrix> modifiedCopy(const Matrix& A, Layout layout, const RowFunction& change);

// 5-point Laplacian on an nx x ny grid, Dirichlet boundary (SPD).
Teuchos::RCP<Matrix> laplacian2D(int nx, int ny, Layout layout,
                                 const Teuchos::RCP<const Comm>& comm);
// 7-point Laplacian on an n x n x n grid (SPD).
Teuchos::RCP<Matrix> laplacian3D(int n, Layout layout, const Teuchos::RCP<const Comm>& comm);
// [K B^T; B 0], K the nx x nx Laplacian, B m rows u_k - u_{k+1} = ... (symmetric indefinite,
// exactly m negative eigenvalues).
Teuchos::RCP<Matrix> saddlePoint(int nx, int m, Layout layout,
                                 const Teuchos::RCP<const Comm>& comm);
// -Laplace(u) + a (du/dx + du/dy), upwinded on an nx x nx grid (non-symmetric M-matrix).
Teuchos::RCP<Matrix> convectionDiffusion(int nx, double a, Layout layout,
                                         const Teuchos::RCP<const Comm>& comm);
// Symmetric indefinite, 5-point pattern on an nx x nx grid with tiny diagonal entries (~1e-10):
// a symmetric factorization must delay most pivots.
Teuchos::RCP<Matrix> tinyDiagonalIndefinite(int nx, Layout layout,
                                            const Teuchos::RCP<const Comm>& comm);
// tridiag(-1, 2, -1) of order n (det = n + 1).
Teuchos::RCP<Matrix> tridiagonal(GO n, Layout layout, const Teuchos::RCP<const Comm>& comm);
// diag(d(0), ..., d(n-1)).
Teuchos::RCP<Matrix> diagonal(GO n, const std::function<double(GO)>& d, Layout layout,
                              const Teuchos::RCP<const Comm>& comm);

// x with solver.setMatrix(A, false) then solver.solve(b, x).
Teuchos::RCP<MultiVector> solved(LinearSolver& solver, const Teuchos::RCP<Matrix>& A,
                                 const MultiVector& b);
// Right-hand side with `columns` columns, b(g, j) a smooth function of the global id g.
Teuchos::RCP<MultiVector> rightHandSide(const Matrix& A, size_t columns);
// Column `col` of v, on every rank, indexed by global id.
std::vector<double> gathered(const MultiVector& v, size_t col);
// max_j ||b_j - A x_j|| / ||b_j||.
double relativeResidual(const Matrix& A, const MultiVector& b, const MultiVector& x);
// max_j ||b_j - A x_j||_inf / (||A||_inf ||x_j||_inf + ||b_j||_inf): the normwise backward
// error, what a solver can promise whatever the matrix' condition (a direct solve's is ~1e-16).
double backwardError(const Matrix& A, const MultiVector& b, const MultiVector& x);
// max_j ||x_j - y_j|| / ||y_j||, comparing by global id (x and y may have different maps).
double relativeDifference(const MultiVector& x, const MultiVector& y);

}  // namespace contactlab::test
