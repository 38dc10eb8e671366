#include "core/fem/ReferenceElement.hpp"

#include <array>
#include <memory>

namespace contactlab {
namespace {

// Reference node coordinates, copied from gmsh::model::mesh::getElementProperties (gmsh 4.8.4)
// and checked against it by the unit tests.
// clang-format off
const std::vector<double> kLine3 = {-1, 1, 0};
const std::vector<double> kTri6 = {0, 0,  1, 0,  0, 1,  0.5, 0,  0.5, 0.5,  0, 0.5};
const std::vector<double> kQuad9 = {-1, -1,  1, -1,  1, 1,  -1, 1,      // corners
                                    0, -1,  1, 0,  0, 1,  -1, 0,        // edges 01 12 23 30
                                    0, 0};                              // centre
const std::vector<double> kTet10 = {0, 0, 0,  1, 0, 0,  0, 1, 0,  0, 0, 1,
                                    0.5, 0, 0,  0.5, 0.5, 0,  0, 0.5, 0,   // edges 01 12 20
                                    0, 0, 0.5,  0, 0.5, 0.5,  0.5, 0, 0.5}; // edges 03 23 13
const std::vector<double> kHex27 = {
    -1, -1, -1,  1, -1, -1,  1, 1, -1,  -1, 1, -1,  // corners 0-3
    -1, -1, 1,   1, -1, 1,   1, 1, 1,   -1, 1, 1,   // corners 4-7
    0, -1, -1,  -1, 0, -1,  -1, -1, 0,  1, 0, -1,   // edges 01 03 04 12
    1, -1, 0,   0, 1, -1,   1, 1, 0,    -1, 1, 0,   // edges 15 23 26 37
    0, -1, 1,   -1, 0, 1,   1, 0, 1,    0, 1, 1,    // edges 45 47 56 67
    0, 0, -1,  0, -1, 0,  -1, 0, 0,  1, 0, 0,  0, 1, 0,  0, 0, 1,  // faces 0321 0154 0473
                                                                   //       1265 2376 4567
    0, 0, 0};                                                      // centre
// clang-format on
// Tri6 and tet10 edge nodes, as pairs of vertices, in gmsh order.
const std::vector<int> kTriEdges = {0, 1, 1, 2, 2, 0};
const std::vector<int> kTetEdges = {0, 1, 1, 2, 2, 0, 0, 3, 2, 3, 1, 3};

// The first `count` nodes of a table (linear elements are the corners of quadratic ones).
std::vector<double> firstNodes(const std::vector<double>& table, int dim, int count) {
  return std::vector<double>(table.begin(), table.begin() + dim * count);
}

}  // namespace

const ReferenceElement& ReferenceElement::get(ElementType type) {
  // Built all at once in a function-local static: thread-safe and cheap (13 tiny objects).
  static const std::array<std::unique_ptr<ReferenceElement>, 13> cache = [] {
    std::array<std::unique_ptr<ReferenceElement>, 13> all;
    for (std::size_t t = 0; t < all.size(); ++t)
      all[t].reset(new ReferenceElement(static_cast<ElementType>(t)));
    return all;
  }();
  return *cache.at(static_cast<std::size_t>(type));
}

ReferenceElement::ReferenceElement(ElementType type)
    : type_(type), dim_(info(type).dim), numNodes_(info(type).nodes), order_(info(type).order) {
  using ET = ElementType;
  switch (type) {
    case ET::Point1:
      family_ = Family::Point;
      break;
    case ET::Line2:
    case ET::Line3:
      family_ = Family::TensorLagrange;
      nodes_ = firstNodes(kLine3, 1, numNodes_);
      break;
    case ET::Quad4:
    case ET::Quad9:
      family_ = Family::TensorLagrange;
      nodes_ = firstNodes(kQuad9, 2, numNodes_);
      break;
    case ET::Hex8:
    case ET::Hex27:
      family_ = Family::TensorLagrange;
      nodes_ = firstNodes(kHex27, 3, numNodes_);
      break;
    case ET::Quad8:
      family_ = Family::Serendipity;
      nodes_ = firstNodes(kQuad9, 2, numNodes_);
      break;
    case ET::Hex20:
      family_ = Family::Serendipity;
      nodes_ = firstNodes(kHex27, 3, numNodes_);
      break;
    case ET::Tri3:
    case ET::Tri6:
      family_ = Family::Simplex;
      nodes_ = firstNodes(kTri6, 2, numNodes_);
      edgeVertices_ = kTriEdges;
      break;
    case ET::Tet4:
    case ET::Tet10:
      family_ = Family::Simplex;
      nodes_ = firstNodes(kTet10, 3, numNodes_);
      edgeVertices_ = kTetEdges;
      break;
  }
  if (family_ == Family::TensorLagrange) {
    index1d_.resize(nodes_.size());
    for (std::size_t k = 0; k < nodes_.size(); ++k)
      index1d_[k] = nodes_[k] < -0.5 ? 0 : (nodes_[k] > 0.5 ? 1 : 2);
  }
}

void ReferenceElement::shape(const double* xi, double* N) const {
  switch (family_) {
    case Family::Point:
      N[0] = 1.0;
      return;
    case Family::TensorLagrange:
      return tensorShape(xi, N, nullptr);
    case Family::Serendipity:
      return serendipityShape(xi, N, nullptr);
    case Family::Simplex:
      return simplexShape(xi, N, nullptr);
  }
}

void ReferenceElement::shapeDerivatives(const double* xi, double* dN) const {
  switch (family_) {
    case Family::Point:
      return;
    case Family::TensorLagrange:
      return tensorShape(xi, nullptr, dN);
    case Family::Serendipity:
      return serendipityShape(xi, nullptr, dN);
    case Family::Simplex:
      return simplexShape(xi, nullptr, dN);
  }
}

void ReferenceElement::tensorShape(const double* xi, double* N, double* dN) const {
  // 1D Lagrange polynomials per direction, indexed like index1d_.
  double l[3][3], dl[3][3];
  for (int i = 0; i < dim_; ++i) {
    const double x = xi[i];
    if (order_ == 1) {
      l[i][0] = 0.5 * (1 - x), l[i][1] = 0.5 * (1 + x);
      dl[i][0] = -0.5, dl[i][1] = 0.5;
    } else {
      l[i][0] = 0.5 * x * (x - 1), l[i][1] = 0.5 * x * (x + 1), l[i][2] = 1 - x * x;
      dl[i][0] = x - 0.5, dl[i][1] = x + 0.5, dl[i][2] = -2 * x;
    }
  }
  for (int a = 0; a < numNodes_; ++a) {
    const int* id = &index1d_[a * dim_];
    if (N) {
      double v = 1.0;
      for (int i = 0; i < dim_; ++i)
        v *= l[i][id[i]];
      N[a] = v;
    }
    if (dN) {
      for (int j = 0; j < dim_; ++j) {
        double v = dl[j][id[j]];
        for (int i = 0; i < dim_; ++i)
          if (i != j) v *= l[i][id[i]];
        dN[a * dim_ + j] = v;
      }
    }
  }
}

void ReferenceElement::serendipityShape(const double* xi, double* N, double* dN) const {
  const double cornerScale = dim_ == 2 ? 0.25 : 0.125;
  const double edgeScale = 2 * cornerScale;
  for (int a = 0; a < numNodes_; ++a) {
    const double* c = &nodes_[a * dim_];
    double p[3];  // 1 + xi_i c_i
    int zero = -1;
    for (int i = 0; i < dim_; ++i) {
      p[i] = 1 + xi[i] * c[i];
      if (c[i] == 0.0) zero = i;
    }
    if (zero < 0) {
      // Corner: scale * prod(p) * (sum xi_i c_i - (dim - 1)).
      double s = 1 - dim_, prod = cornerScale;
      for (int i = 0; i < dim_; ++i)
        s += xi[i] * c[i], prod *= p[i];
      if (N) N[a] = prod * s;
      if (dN) {
        for (int j = 0; j < dim_; ++j) {
          double others = cornerScale;
          for (int i = 0; i < dim_; ++i)
            if (i != j) others *= p[i];
          dN[a * dim_ + j] = c[j] * others * (s + p[j]);
        }
      }
    } else {
      // Edge mid node: scale * (1 - xi_k^2) * prod_{i != k} p_i.
      const double bubble = 1 - xi[zero] * xi[zero];
      double prod = edgeScale;
      for (int i = 0; i < dim_; ++i)
        if (i != zero) prod *= p[i];
      if (N) N[a] = bubble * prod;
      if (dN) {
        for (int j = 0; j < dim_; ++j) {
          if (j == zero) {
            dN[a * dim_ + j] = -2 * xi[zero] * prod;
          } else {
            double others = edgeScale * bubble;
            for (int i = 0; i < dim_; ++i)
              if (i != j && i != zero) others *= p[i];
            dN[a * dim_ + j] = c[j] * others;
          }
        }
      }
    }
  }
}

void ReferenceElement::simplexShape(const double* xi, double* N, double* dN) const {
  // Barycentric coordinates: L0 = 1 - sum xi, L_{i+1} = xi_i; dL_v/dxi_j is -1 for v = 0 and
  // delta_{v-1,j} otherwise.
  double L[4];
  L[0] = 1.0;
  for (int i = 0; i < dim_; ++i)
    L[0] -= xi[i], L[i + 1] = xi[i];
  auto dL = [](int v, int j) { return v == 0 ? -1.0 : (v - 1 == j ? 1.0 : 0.0); };
  const int vertices = dim_ + 1;
  for (int v = 0; v < vertices; ++v) {
    const double f = order_ == 1 ? 1.0 : 4 * L[v] - 1;
    if (N) N[v] = order_ == 1 ? L[v] : L[v] * (2 * L[v] - 1);
    if (dN)
      for (int j = 0; j < dim_; ++j)
        dN[v * dim_ + j] = f * dL(v, j);
  }
  if (order_ == 1) return;
  for (int e = 0; vertices + e < numNodes_; ++e) {
    const int a = vertices + e, i = edgeVertices_[2 * e], k = edgeVertices_[2 * e + 1];
    if (N) N[a] = 4 * L[i] * L[k];
    if (dN)
      for (int j = 0; j < dim_; ++j)
        dN[a * dim_ + j] = 4 * (L[k] * dL(i, j) + L[i] * dL(k, j));
  }
}

}  // namespace contactlab
