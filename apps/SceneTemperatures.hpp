#pragma once
// The scene's Temperature section: one sublist per element block, its prescribed temperature
// T(t) = T_ref + (Value - T_ref) f(t) (core/problem/Loads.hpp, BlockTemperature), with T_ref
// the block material's Reference Temperature.
#include "core/problem/SolidModel.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace contactlab {

// Reads the validated section; model.materials must be built. Throws InputError naming `where`
// and the entry for a name that is not a block of Materials, a block whose material takes no
// temperature (Material::referenceTemperature), or a Value that is not finite.
std::vector<BlockTemperature> blockTemperatures(const Teuchos::ParameterList& section,
                                                const SolidModel& model, double endTime,
                                                const std::string& where);

}  // namespace contactlab
