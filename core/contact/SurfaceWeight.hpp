#pragma once
// The weight of a contact surface's measure at a point: the integrals over a surface (tributary
// areas, mortar integrals) take dA w(x) instead of dA. An axisymmetric model's surfaces are
// rings, w = 2 pi r (r = x[0]); an empty function is w = 1. core/contact knows nothing else of
// the model: the caller (formulations/ContactProblem) chooses the weight.
#include <functional>

namespace contactlab {

using SurfaceWeight = std::function<double(const double* x)>;

}  // namespace contactlab
