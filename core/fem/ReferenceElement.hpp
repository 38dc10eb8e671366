#pragma once
// Lagrange reference elements on gmsh's reference domains and in gmsh's node order: lines and
// tensor cells on [-1,1]^d, simplices on the unit simplex with node 0 at the origin. Quad8 and
// hex20 are serendipity elements. shape()/shapeDerivatives() run in the assembly inner loop:
// they never allocate.
#include "core/mesh/ElementType.hpp"

#include <vector>

namespace contactlab {

class ReferenceElement {
 public:
  // One shared instance per type, built on first use.
  static const ReferenceElement& get(ElementType type);

  ElementType type() const { return type_; }
  int dim() const { return dim_; }
  int numNodes() const { return numNodes_; }
  // Reference coordinates of the nodes, dim() per node, in gmsh order.
  const std::vector<double>& nodeCoordinates() const { return nodes_; }

  // N[a] at reference point xi (dim() coordinates).
  void shape(const double* xi, double* N) const;
  // dN[a * dim() + i] = dN_a / dxi_i.
  void shapeDerivatives(const double* xi, double* dN) const;

 private:
  enum class Family { Point, TensorLagrange, Serendipity, Simplex };

  explicit ReferenceElement(ElementType type);
  void tensorShape(const double* xi, double* N, double* dN) const;
  void serendipityShape(const double* xi, double* N, double* dN) const;
  void simplexShape(const double* xi, double* N, double* dN) const;

  ElementType type_;
  int dim_;
  int numNodes_;
  int order_;
  Family family_;
  std::vector<double> nodes_;
  // Tensor Lagrange: 1D node index per node and direction (0: -1, 1: +1, 2: 0).
  std::vector<int> index1d_;
  // Quadratic simplices: the two vertices of each edge node.
  std::vector<int> edgeVertices_;
};

}  // namespace contactlab
