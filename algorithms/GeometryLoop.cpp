#include "algorithms/GeometryLoop.hpp"

#include <algorithm>

namespace contactlab {

FixedPointLoop::MovedStateTest GeometryLoop::testMovedState(const Vector& x, double t,
                                                            double reference, Vector& residual) {
  // Newton converged at a geometry frozen at this very iterate: when the update changes the
  // residual by less than the geometry tolerance, the fixed point has converged too.
  system_.assemble(x, t, &residual, false);
  MovedStateTest test;
  test.tested = true;
  test.residual = residual.norm2();
  test.target = std::max(absoluteTolerance_, tolerance_ * reference);
  return test;
}

}  // namespace contactlab
