#pragma once
// The scene `contactlab run` runs when given none: a plane-strain cantilever (quad8) clamped on
// the left and loaded by a downward traction on the right, in three load steps. A few seconds.
namespace contactlab {

inline constexpr const char* kDefaultScene = R"(contactlab:
  Name: default-cantilever
  Description: Plane-strain cantilever, clamped left, shear traction on the right end
  Mesh:
    Type: rectangle
    rectangle: {Lx: 10.0, Ly: 1.0, nx: 40, ny: 4, Element: quad8}
  Materials:
    body:
      Type: linear-elastic
      linear-elastic: {E: 1000.0, nu: 0.3}
  Dirichlet:
    clamp: {Group: left, Components: xy, Value: 0.0}
  Loads:
    shear: {Type: traction, Group: right, Vector: [0.0, -1.0]}
  Load Steps: {Steps: 3}
  Output:
    Probes:
      tip: {Point: [10.0, 0.5, 0.0], Field: displacement}
      root: {Point: [0.0, 1.0, 0.0], Field: stress}
)";

}  // namespace contactlab
