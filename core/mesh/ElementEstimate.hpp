#pragma once
// How many elements a built-in generator would make, before gmsh runs: a request that would
// exhaust memory (nx = ny = 100 000; a 3D Size Contact of 1e-5) is refused in a sentence
// instead of aborting with bad_alloc or meshing for minutes. Structured generators give exact
// counts; graded ones integrate the size field over the body (elements per h^dim of the cell
// kind: ~2.3 triangles or 1.2 quads per h^2, ~6 tetrahedra per h^3, 4 hexahedra per tetrahedron
// when hexes are tets split): an order of magnitude, checked against gmsh's counts on the
// generators' defaults (ElementEstimateTest).
#include "core/mesh/MeshGenerators.hpp"

#include <string>

namespace contactlab {

// Scene key of the limit, in every generator's parameters, and its default.
constexpr const char* kMaxElementsKey = "Max Elements";
constexpr int kDefaultMaxElements = 2000000;

double estimateElements(const RectangleParams& p);
double estimateElements(const BoxParams& p);
double estimateElements(const RingSectorParams& p);
double estimateElements(const HalfDiscParams& p);
double estimateElements(const RollerOnBaseParams& p);
double estimateElements(const HalfSphereParams& p);
double estimateElements(const StackedBlocks2DParams& p);
double estimateElements(const StackedBlocks3DParams& p);
double estimateElements(const BladeRootParams& p);
double estimateElements(const DieOnSlabParams& p);
double estimateElements(const TubeInTubesheetParams& p);

// Throws std::invalid_argument when estimate > limit, naming the generator and the key.
void requireElementLimit(const std::string& generator, double estimate, int limit);

}  // namespace contactlab
