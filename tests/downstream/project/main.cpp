// Uses contactlab only through its installed headers and exported targets.
#include "core/mesh/Mesh.hpp"
#include "linear/LinearSolver.hpp"

#include <cmath>
#include <iostream>

int main() {
  using contactlab::ElementType;
  const int nodes = contactlab::info(ElementType::Hex27).nodes;  // contactlab::core
  std::cout << "Hex27 nodes: " << nodes << "\n";

  contactlab::Mesh mesh;
  mesh.dim = 3;
  mesh.source = "downstream";
  mesh.coords.assign(3 * 27, 0.0);
  contactlab::CellGroup body;
  body.name = "body";
  body.dim = 3;
  body.type = ElementType::Hex27;
  for (int i = 0; i < 27; ++i)
    body.nodes.push_back(i);
  body.tags.push_back(1);
  mesh.blocks.push_back(body);

  contactlab::Determinant det;  // contactlab::linear: det = 0.5 * 2^3 = 4
  det.mantissa = 0.5;
  det.exponent = 3;
  const double log10Det = det.log10Abs();
  std::cout << "mesh: " << mesh.numNodes() << " nodes, " << mesh.numElements()
            << " elements; log10 det = " << log10Det << "\n";

  const bool ok = nodes == 27 && mesh.numNodes() == 27 && mesh.numElements() == 1 &&
                  mesh.blockNames().size() == 1 && det.sign() == 1 &&
                  std::abs(log10Det - std::log10(4.0)) < 1e-12;
  std::cout << (ok ? "OK: Hex27 has 27 nodes" : "FAILED") << std::endl;
  return ok ? 0 : 1;
}
