#pragma once
// The scene's Contact section: each zone's surfaces (or obstacle) checked against the mesh, its
// formulation built with the automatic coefficients filled in from the model, its
// discretization chosen, and the combinations that cannot work refused with the reason.
#include "apps/SceneModel.hpp"

namespace contactlab {

// Reads Contact/<zone> for every zone into sm.contact, with the notes (automatic choices),
// advice (poor but runnable choices) and automatic coefficients in sm. Needs sm.model (mesh,
// materials) and sm.solverOptions. Throws InputError naming `where` and the key.
void readContactZones(const Teuchos::ParameterList& contact, SceneModel& sm,
                      const std::string& where);

}  // namespace contactlab
