#pragma once
// The conditions a plane-stress SolidModel (SolidModel::planeStress) must meet, each refused with
// an InputError naming what is wrong:
//  - a 2D mesh, and not axisymmetric as well;
//  - no follower pressure: the facets' current area would need the plate's current thickness
//    there, which the pressure kernel does not know (a finite-strain block's pressure follows by
//    default, so it must be given Follower: false).
#include "core/problem/SolidModel.hpp"

namespace contactlab {

void checkPlaneStressModel(const SolidModel& model);

}  // namespace contactlab
