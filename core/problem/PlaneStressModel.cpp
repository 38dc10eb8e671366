#include "core/problem/PlaneStressModel.hpp"

#include "base/InputError.hpp"

namespace contactlab {

void checkPlaneStressModel(const SolidModel& model) {
  if (!model.planeStress) return;
  const Mesh& mesh = *model.mesh;
  if (mesh.dim != 2)
    throw InputError("a plane-stress model needs a 2D mesh (a plate loaded in its plane), but " +
                     mesh.source + " is " + std::to_string(mesh.dim) + "D");
  if (model.axisymmetric) throw InputError("a model cannot be both plane stress and axisymmetric");
  if (const SurfaceLoad* load = model.followerPressure())
    throw InputError("load '" + load->name +
                     "': a plane-stress model has no follower pressure (the facets' current "
                     "area needs the plate's current thickness; on a finite-strain block a "
                     "pressure follows by default): give it Follower: false, a dead pressure "
                     "on the reference facets");
}

}  // namespace contactlab
