#pragma once
// The time function of a prescribed value in a scene (Dirichlet, load, obstacle, block
// temperature): the keys Function, Start Time, Stop Time, Times, Factors of a validated
// sublist, checked against the scene's End Time.
#include "core/problem/Loads.hpp"

#include <Teuchos_ParameterList.hpp>

#include <string>

namespace contactlab {

// Throws InputError naming `where` (the scene file) and `path` (the sublist) for a ramp outside
// [0, End Time], or a table whose Times and Factors do not match or do not increase.
LoadFunction loadFunction(const Teuchos::ParameterList& p, double endTime, const std::string& where,
                          const std::string& path);

}  // namespace contactlab
