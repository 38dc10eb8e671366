#include "core/problem/SlotOperator.hpp"

#include <initializer_list>
#include <stdexcept>

namespace contactlab {
namespace {

// Declares the rows of `op`: their slots, which are diagonal, and for each displacement component
// the rows its columns touch.
void declareRows(SlotOperator& op, int dim, int numNodes, std::initializer_list<int> slots,
                 std::initializer_list<int> diagonal,
                 std::initializer_list<std::initializer_list<int>> componentRows) {
  if (numNodes * dim > SlotOperator::kMaxDofs)
    throw std::invalid_argument("SlotOperator: too many dofs");
  op.dim = dim;
  op.numDofs = numNodes * dim;
  op.rows = static_cast<int>(slots.size());
  int r = 0;
  for (int s : slots)
    op.slot[r++] = s;
  op.volumetricCount = 0;
  for (int k = 0; k < op.rows; ++k)
    op.volumetric[k] = false;
  for (int k : diagonal) {
    op.volumetric[k] = true;
    ++op.volumetricCount;
  }
  int c = 0;
  for (const auto& list : componentRows) {
    op.componentRowCount[c] = 0;
    for (int row : list)
      op.componentRows[c][op.componentRowCount[c]++] = row;
    ++c;
  }
  for (int k = 0; k < op.rows; ++k)
    for (int j = 0; j < op.numDofs; ++j)
      op.B[k][j] = 0.0;
}

}  // namespace

// Dof k = node * dim + c: the loops below run over nodes and components, not k % dim.
void SlotOperator::apply(const double* u, double* values) const {
  for (int r = 0; r < rows; ++r)
    values[r] = 0.0;
  for (int node = 0; node < numDofs; node += dim)
    for (int c = 0; c < dim; ++c) {
      const int k = node + c;
      for (int j = 0; j < componentRowCount[c]; ++j) {
        const int r = componentRows[c][j];
        values[r] += B[r][k] * u[k];
      }
    }
}

void SlotOperator::addTransposeProduct(const double* v, double scale, double* out) const {
  for (int node = 0; node < numDofs; node += dim)
    for (int c = 0; c < dim; ++c) {
      const int k = node + c;
      double s = 0.0;
      for (int j = 0; j < componentRowCount[c]; ++j) {
        const int r = componentRows[c][j];
        s += B[r][k] * v[r];
      }
      out[k] += scale * s;
    }
}

void SlotOperator::addProduct(const double* C, double w, double* K, bool upperBlocks) const {
  // CB = w C B (rows x nd), using the sparsity of B's columns; then K's row k is the sum of
  // B[r][k] CB[r] over the rows r that column k touches: contiguous axpys, which vectorize.
  double CB[kMaxRows][kMaxDofs];
  for (int r = 0; r < rows; ++r) {
    const double* Cr = &C[r * rows];
    for (int node = 0; node < numDofs; node += dim)
      for (int c = 0; c < dim; ++c) {
        const int k = node + c;
        double s = 0.0;
        for (int j = 0; j < componentRowCount[c]; ++j) {
          const int m = componentRows[c][j];
          s += Cr[m] * B[m][k];
        }
        CB[r][k] = w * s;
      }
  }
  for (int node = 0; node < numDofs; node += dim)
    for (int c = 0; c < dim; ++c) {
      const int i = node + c;
      double* row = &K[i * numDofs];
      const int first = upperBlocks ? node : 0;
      for (int j = 0; j < componentRowCount[c]; ++j) {
        const int r = componentRows[c][j];
        const double b = B[r][i];
        if (b == 0.0) continue;
        const double* cb = CB[r];
        for (int k = first; k < numDofs; ++k)
          row[k] += b * cb[k];
      }
    }
}

void smallStrainOperator(int dim, bool axisymmetric, int numNodes, const double* N,
                         const double* dNdx, double r, SlotOperator& op) {
  if (dim == 3) {
    // xx yy zz xy yz xz
    declareRows(op, 3, numNodes, {0, 1, 2, 3, 4, 5}, {0, 1, 2}, {{0, 3, 5}, {1, 3, 4}, {2, 4, 5}});
    for (int a = 0; a < numNodes; ++a) {
      const double gx = dNdx[3 * a], gy = dNdx[3 * a + 1], gz = dNdx[3 * a + 2];
      const int x = 3 * a, y = x + 1, z = x + 2;
      op.B[0][x] = gx;
      op.B[1][y] = gy;
      op.B[2][z] = gz;
      op.B[3][x] = gy, op.B[3][y] = gx;
      op.B[4][y] = gz, op.B[4][z] = gy;
      op.B[5][x] = gz, op.B[5][z] = gx;
    }
  } else if (axisymmetric) {
    // rr zz tt rz
    declareRows(op, 2, numNodes, {0, 1, 2, 3}, {0, 1, 2}, {{0, 2, 3}, {1, 3}});
    for (int a = 0; a < numNodes; ++a) {
      const double gr = dNdx[2 * a], gz = dNdx[2 * a + 1];
      const int x = 2 * a, y = x + 1;
      op.B[0][x] = gr;
      op.B[1][y] = gz;
      op.B[2][x] = N[a] / r;
      op.B[3][x] = gz, op.B[3][y] = gr;
    }
  } else {
    // xx yy xy (Voigt 0, 1, 3)
    declareRows(op, 2, numNodes, {0, 1, 3}, {0, 1}, {{0, 2}, {1, 2}});
    for (int a = 0; a < numNodes; ++a) {
      const double gx = dNdx[2 * a], gy = dNdx[2 * a + 1];
      const int x = 2 * a, y = x + 1;
      op.B[0][x] = gx;
      op.B[1][y] = gy;
      op.B[2][x] = gy, op.B[2][y] = gx;
    }
  }
}

void deformationGradientOperator(int dim, bool axisymmetric, int numNodes, const double* N,
                                 const double* dNdX, double R, SlotOperator& op) {
  if (dim == 3) {
    declareRows(op, 3, numNodes, {0, 1, 2, 3, 4, 5, 6, 7, 8}, {0, 4, 8},
                {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
    for (int a = 0; a < numNodes; ++a)
      for (int i = 0; i < 3; ++i)
        for (int J = 0; J < 3; ++J)
          op.B[3 * i + J][3 * a + i] = dNdX[3 * a + J];
  } else if (axisymmetric) {
    // rr rz zr zz tt (F slots 0, 1, 3, 4, 8)
    declareRows(op, 2, numNodes, {0, 1, 3, 4, 8}, {0, 3, 4}, {{0, 1, 4}, {2, 3}});
    for (int a = 0; a < numNodes; ++a) {
      const double gR = dNdX[2 * a], gZ = dNdX[2 * a + 1];
      const int x = 2 * a, y = x + 1;
      op.B[0][x] = gR;
      op.B[1][x] = gZ;
      op.B[2][y] = gR;
      op.B[3][y] = gZ;
      op.B[4][x] = N[a] / R;
    }
  } else {
    // xx xy yx yy (F slots 0, 1, 3, 4)
    declareRows(op, 2, numNodes, {0, 1, 3, 4}, {0, 3}, {{0, 1}, {2, 3}});
    for (int a = 0; a < numNodes; ++a) {
      const double gX = dNdX[2 * a], gY = dNdX[2 * a + 1];
      const int x = 2 * a, y = x + 1;
      op.B[0][x] = gX;
      op.B[1][x] = gY;
      op.B[2][y] = gX;
      op.B[3][y] = gY;
    }
  }
}

void restrictToSlots(const SlotOperator& op, const double* M, int ld, double* out) {
  for (int r = 0; r < op.rows; ++r)
    for (int m = 0; m < op.rows; ++m)
      out[r * op.rows + m] = M[op.slot[r] * ld + op.slot[m]];
}

std::array<double, 9> deformationGradient(const SlotOperator& op, const double* u) {
  std::array<double, 9> F = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  double values[SlotOperator::kMaxRows];
  op.apply(u, values);
  for (int r = 0; r < op.rows; ++r)
    F[op.slot[r]] += values[r];
  return F;
}

void logJacobianGradient(const SlotOperator& op, const std::array<double, 9>& Finv, double* g) {
  for (int r = 0; r < op.rows; ++r) {
    const int i = op.slot[r] / 3, J = op.slot[r] % 3;
    g[r] = Finv[J * 3 + i];
  }
}

void logJacobianHessian(const SlotOperator& op, const std::array<double, 9>& Finv, double* L) {
  for (int r = 0; r < op.rows; ++r) {
    const int i = op.slot[r] / 3, J = op.slot[r] % 3;
    for (int m = 0; m < op.rows; ++m) {
      const int k = op.slot[m] / 3, l = op.slot[m] % 3;
      L[r * op.rows + m] = -Finv[J * 3 + k] * Finv[l * 3 + i];
    }
  }
}

void addOuterProduct(const double* x, const double* y, double scale, int nd, int dim, double* K,
                     bool upperBlocks) {
  for (int i = 0; i < nd; ++i) {
    const double xi = scale * x[i];
    if (xi == 0.0) continue;
    double* row = &K[i * nd];
    const int first = upperBlocks ? i / dim * dim : 0;
    for (int k = first; k < nd; ++k)
      row[k] += xi * y[k];
  }
}

void mirrorUpperBlocks(int nd, int dim, double* K) {
  const int n = nd / dim;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      for (int i = 0; i < dim; ++i)
        for (int k = 0; k < dim; ++k)
          K[(b * dim + k) * nd + a * dim + i] += K[(a * dim + i) * nd + b * dim + k];
}

}  // namespace contactlab
