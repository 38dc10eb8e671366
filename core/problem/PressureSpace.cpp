#include "core/problem/PressureSpace.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace contactlab {

PressureSpace::PressureSpace(int degree, int dim)
    : degree_(degree), dim_(dim), size_(degree == 0 ? 1 : dim + 1) {
  if ((degree != 0 && degree != 1) || (dim != 2 && dim != 3))
    throw std::invalid_argument("PressureSpace: degree 0 or 1 in 2D or 3D");
}

void PressureSpace::checkKernel(const char* kernel, int degree, int numPoints) {
  if (degree != 0 && degree != 1)
    throw std::invalid_argument(std::string(kernel) + ": pressure degree 0 or 1");
  if (numPoints > kMaxPoints)
    throw std::invalid_argument(std::string(kernel) + ": too many quadrature points");
}

void PressureSpace::setElement(int numPoints, const double* points, const double* measures) {
  if (numPoints > kMaxPoints) throw std::invalid_argument("PressureSpace: too many points");
  numPoints_ = numPoints;
  if (degree_ == 0) {  // the mean: psi = 1, weight = w_q / V (points unread)
    double volume = 0.0;
    for (int q = 0; q < numPoints; ++q)
      volume += measures[q];
    if (!(std::fabs(volume) > 0))
      throw std::invalid_argument("PressureSpace: the element's Gram matrix is singular");
    const double inverse = 1.0 / volume;  // as the Gram inverse below, to the last bit
    for (int q = 0; q < numPoints; ++q) {
      psi_[q][0] = 1.0;
      weight_[0][q] = inverse * measures[q];
    }
    return;
  }
  double volume = 0.0, centre[3] = {0.0, 0.0, 0.0};
  for (int q = 0; q < numPoints; ++q) {
    volume += measures[q];
    for (int i = 0; i < dim_; ++i)
      centre[i] += measures[q] * points[3 * q + i];
  }
  for (int i = 0; i < dim_; ++i)
    centre[i] /= volume;
  // The size scaling: the largest distance of a point from the centre (points are inside).
  double size = 0.0;
  for (int q = 0; q < numPoints; ++q)
    for (int i = 0; i < dim_; ++i)
      size = std::fmax(size, std::fabs(points[3 * q + i] - centre[i]));
  if (!(size > 0)) size = 1.0;
  for (int q = 0; q < numPoints; ++q) {
    psi_[q][0] = 1.0;
    if (degree_ == 1)
      for (int i = 0; i < dim_; ++i)
        psi_[q][1 + i] = (points[3 * q + i] - centre[i]) / size;
  }
  // Gram matrix M and its inverse by Gauss-Jordan with partial pivoting (size <= 4).
  const int n = size_;
  double M[kMaxSize][2 * kMaxSize] = {};
  for (int q = 0; q < numPoints; ++q)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        M[i][j] += measures[q] * psi_[q][i] * psi_[q][j];
  const double scale = M[0][0];
  for (int i = 0; i < n; ++i)
    M[i][n + i] = 1.0;
  for (int c = 0; c < n; ++c) {
    int p = c;
    for (int r = c + 1; r < n; ++r)
      if (std::fabs(M[r][c]) > std::fabs(M[p][c])) p = r;
    if (!(std::fabs(M[p][c]) > 1e-12 * scale))
      throw std::invalid_argument("PressureSpace: the element's Gram matrix is singular");
    if (p != c)
      for (int k = 0; k < 2 * n; ++k)
        std::swap(M[p][k], M[c][k]);
    const double d = M[c][c];
    for (int k = 0; k < 2 * n; ++k)
      M[c][k] /= d;
    for (int r = 0; r < n; ++r) {
      if (r == c) continue;
      const double f = M[r][c];
      for (int k = 0; k < 2 * n; ++k)
        M[r][k] -= f * M[c][k];
    }
  }
  for (int i = 0; i < n; ++i)
    for (int q = 0; q < numPoints; ++q) {
      double s = 0.0;
      for (int j = 0; j < n; ++j)
        s += M[i][n + j] * psi_[q][j];
      weight_[i][q] = s * measures[q];
    }
}

double PressureSpace::projectedAt(int q, const double* f) const {
  double value = 0.0;
  for (int i = 0; i < size_; ++i) {
    double c = 0.0;
    for (int p = 0; p < numPoints_; ++p)
      c += weight_[i][p] * f[p];
    value += psi_[q][i] * c;
  }
  return value;
}

}  // namespace contactlab
