#pragma once
// The algorithm presets (Algorithm/Method) and the composition of a step's loops.
//
// A preset says which of the contact problem's non-smooth parts Newton handles; the others are
// fixed points around it (doc/theory.md, the seed's table). Algorithm/Contact Statuses,
// Friction Threshold and Geometry override it per loop (StaticSolverOptions::from resolves
// them). composeLoops turns the resolved choice into StaticSolver's ordered list of loops,
// innermost first: statuses, thresholds, geometry. To add a loop: a FixedPointLoop class, its
// column here, its key in StaticSolverOptions, one entry in composeLoops (doc/architecture.md).
#include "algorithms/FixedPointLoop.hpp"
#include "core/problem/NonlinearSystem.hpp"
#include "formulations/ContactControls.hpp"

#include <memory>
#include <string>
#include <vector>

namespace contactlab {

struct StaticSolverOptions;

struct AlgorithmPreset {
  std::string name;  // Algorithm/Method
  bool statusesInNewton, thresholdsInNewton, geometryInNewton;
};

// Every preset, in the order the scene schema lists them.
const std::vector<AlgorithmPreset>& algorithmPresets();
// The preset named `name`; std::invalid_argument when there is none.
const AlgorithmPreset& algorithmPreset(const std::string& name);

// The step's loops, innermost first, each in Newton or a fixed point as `options` resolved.
// Without contact (controls null) only the geometry loop, which the system alone serves.
std::vector<std::unique_ptr<FixedPointLoop>> composeLoops(const StaticSolverOptions& options,
                                                          NonlinearSystem& system,
                                                          ContactControls* controls);

}  // namespace contactlab
