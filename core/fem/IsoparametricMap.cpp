#include "core/fem/IsoparametricMap.hpp"

#include <cmath>

namespace contactlab {

void jacobian(int dim, int numNodes, const double* x, const double* dNdxi, double* J) {
  for (int k = 0; k < dim * dim; ++k)
    J[k] = 0.0;
  for (int a = 0; a < numNodes; ++a)
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j)
        J[i * dim + j] += x[3 * a + i] * dNdxi[a * dim + j];
}

double invert(int dim, const double* J, double* Jinv) {
  if (dim == 1) {
    Jinv[0] = 1.0 / J[0];
    return J[0];
  }
  if (dim == 2) {
    const double det = J[0] * J[3] - J[1] * J[2];
    Jinv[0] = J[3] / det, Jinv[1] = -J[1] / det;
    Jinv[2] = -J[2] / det, Jinv[3] = J[0] / det;
    return det;
  }
  const double c00 = J[4] * J[8] - J[5] * J[7];
  const double c01 = J[5] * J[6] - J[3] * J[8];
  const double c02 = J[3] * J[7] - J[4] * J[6];
  const double det = J[0] * c00 + J[1] * c01 + J[2] * c02;
  const double s = 1.0 / det;
  Jinv[0] = c00 * s;
  Jinv[1] = (J[2] * J[7] - J[1] * J[8]) * s;
  Jinv[2] = (J[1] * J[5] - J[2] * J[4]) * s;
  Jinv[3] = c01 * s;
  Jinv[4] = (J[0] * J[8] - J[2] * J[6]) * s;
  Jinv[5] = (J[2] * J[3] - J[0] * J[5]) * s;
  Jinv[6] = c02 * s;
  Jinv[7] = (J[1] * J[6] - J[0] * J[7]) * s;
  Jinv[8] = (J[0] * J[4] - J[1] * J[3]) * s;
  return det;
}

double physicalGradients(int dim, int numNodes, const double* x, const double* dNdxi,
                         double* dNdx) {
  double J[9], Jinv[9];
  jacobian(dim, numNodes, x, dNdxi, J);
  // det J computed as in invert(), but checked before dividing by it.
  double det;
  if (dim == 1)
    det = J[0];
  else if (dim == 2)
    det = J[0] * J[3] - J[1] * J[2];
  else
    det = J[0] * (J[4] * J[8] - J[5] * J[7]) + J[1] * (J[5] * J[6] - J[3] * J[8]) +
          J[2] * (J[3] * J[7] - J[4] * J[6]);
  double scale = 1.0;
  for (int j = 0; j < dim; ++j) {
    double column = 0.0;
    for (int i = 0; i < dim; ++i)
      column += J[i * dim + j] * J[i * dim + j];
    scale *= std::sqrt(column);
  }
  if (!(std::abs(det) > kDegenerateTolerance * scale))
    throw InvalidElementError(InvalidElementError::Kind::Degenerate, "det J", det);
  if (det < 0) throw InvalidElementError(InvalidElementError::Kind::Inverted, "det J", det);
  invert(dim, J, Jinv);
  for (int a = 0; a < numNodes; ++a)
    for (int i = 0; i < dim; ++i) {
      double g = 0.0;
      for (int j = 0; j < dim; ++j)
        g += dNdxi[a * dim + j] * Jinv[j * dim + i];
      dNdx[a * dim + i] = g;
    }
  return det;
}

double facetGeometry(int spaceDim, int numNodes, const double* x, const double* dNdxi,
                     double* normal) {
  const int refDim = spaceDim - 1;
  double t[2][3] = {{0, 0, 0}, {0, 0, 0}};  // tangents dx/dxi_j
  for (int a = 0; a < numNodes; ++a)
    for (int j = 0; j < refDim; ++j)
      for (int i = 0; i < 3; ++i)
        t[j][i] += x[3 * a + i] * dNdxi[a * refDim + j];
  double n[3], scale;
  if (spaceDim == 2) {
    n[0] = t[0][1], n[1] = -t[0][0], n[2] = 0.0;
    // A zero tangent has no reference length: compare with the nodes' extent instead.
    scale = 0.0;
    for (int a = 1; a < numNodes; ++a)
      scale = std::fmax(scale, std::hypot(x[3 * a] - x[0], x[3 * a + 1] - x[1]));
  } else {
    n[0] = t[0][1] * t[1][2] - t[0][2] * t[1][1];
    n[1] = t[0][2] * t[1][0] - t[0][0] * t[1][2];
    n[2] = t[0][0] * t[1][1] - t[0][1] * t[1][0];
    scale = std::sqrt(t[0][0] * t[0][0] + t[0][1] * t[0][1] + t[0][2] * t[0][2]) *
            std::sqrt(t[1][0] * t[1][0] + t[1][1] * t[1][1] + t[1][2] * t[1][2]);
  }
  const double dA = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(dA > kDegenerateTolerance * scale) || dA == 0.0)
    throw InvalidElementError(InvalidElementError::Kind::Degenerate, "dA", dA);
  for (int i = 0; i < 3; ++i)
    normal[i] = n[i] / dA;
  return dA;
}

void interpolatePosition(int numNodes, const double* x, const double* N, double* point) {
  point[0] = point[1] = point[2] = 0.0;
  for (int a = 0; a < numNodes; ++a)
    for (int i = 0; i < 3; ++i)
      point[i] += N[a] * x[3 * a + i];
}

}  // namespace contactlab
