#include "core/problem/AxisymmetricModel.hpp"

#include "base/InputError.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace contactlab {

void checkAxisymmetricModel(const SolidModel& model) {
  if (!model.axisymmetric) return;
  const Mesh& mesh = *model.mesh;
  if (mesh.dim != 2)
    throw InputError("an axisymmetric model needs a 2D mesh (x the radius, y the axis), but " +
                     mesh.source + " is " + std::to_string(mesh.dim) + "D");
  const auto numNodes = static_cast<std::int64_t>(mesh.numNodes());
  double size = 0.0;
  for (std::int64_t n = 0; n < numNodes; ++n)
    size = std::max({size, std::abs(mesh.coords[3 * n]), std::abs(mesh.coords[3 * n + 1])});
  const double tolerance = 1e-10 * size;
  std::set<std::int64_t> radiallyHeld;
  for (const auto& bc : model.dirichlet)
    if (std::find(bc.components.begin(), bc.components.end(), 0) != bc.components.end())
      for (std::int64_t n : mesh.boundaryNodes(bc.group))
        radiallyHeld.insert(n);
  for (std::int64_t n = 0; n < numNodes; ++n) {
    const double r = mesh.coords[3 * n];
    std::ostringstream where;
    where << "node " << mesh.nodeId(n) << " at (" << r << ", " << mesh.coords[3 * n + 1] << ") of "
          << mesh.source;
    if (r < -tolerance)
      throw InputError(where.str() +
                       " has x < 0: an axisymmetric model lies in the half-plane x = r >= 0");
    if (r <= tolerance && !radiallyHeld.count(n))
      throw InputError(where.str() +
                       " is on the axis, where u_r = 0: give a Dirichlet condition on x for "
                       "the group of the nodes on the axis");
  }
}

}  // namespace contactlab
