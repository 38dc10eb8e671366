#pragma once
// The conditions an axisymmetric SolidModel (SolidModel::axisymmetric) must meet before it is
// assembled, each refused with an InputError naming what is wrong:
//  - a 2D mesh, every node at x = r >= 0 (the first node found below the axis is named);
//  - every node on the axis (|x| <= 1e-10 of the mesh's size) with its radial displacement held
//    by a Dirichlet condition on x: on the axis u_r = 0 is the geometry's own condition, and we
//    require it rather than add it so that the reactions list every constraint the user gave.
#include "core/problem/SolidModel.hpp"

namespace contactlab {

void checkAxisymmetricModel(const SolidModel& model);

}  // namespace contactlab
