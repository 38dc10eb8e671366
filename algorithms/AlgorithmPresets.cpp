#include "algorithms/AlgorithmPresets.hpp"

#include "algorithms/GeometryLoop.hpp"
#include "algorithms/StaticSolver.hpp"
#include "algorithms/StatusLoop.hpp"
#include "algorithms/ThresholdLoop.hpp"

#include <stdexcept>

namespace contactlab {

const std::vector<AlgorithmPreset>& algorithmPresets() {
  // name, statuses, thresholds, geometry in Newton (doc/theory.md: PF, NG, NP).
  static const std::vector<AlgorithmPreset> presets = {
      {"fixed-point", false, false, false},
      {"generalized-newton", true, true, true},
      {"partial-newton", true, true, false},
  };
  return presets;
}

const AlgorithmPreset& algorithmPreset(const std::string& name) {
  for (const AlgorithmPreset& p : algorithmPresets())
    if (p.name == name) return p;
  throw std::invalid_argument("Algorithm/Method: no preset named '" + name + "'");
}

std::vector<std::unique_ptr<FixedPointLoop>> composeLoops(const StaticSolverOptions& options,
                                                          NonlinearSystem& system,
                                                          ContactControls* controls) {
  std::vector<std::unique_ptr<FixedPointLoop>> loops;
  if (controls) {
    loops.push_back(std::make_unique<StatusLoop>(*controls, options.statusesInNewton,
                                                 options.maxStatusIterations));
    loops.push_back(std::make_unique<ThresholdLoop>(*controls, options.thresholdsInNewton,
                                                    options.maxThresholdIterations,
                                                    options.thresholdTolerance));
  }
  loops.push_back(std::make_unique<GeometryLoop>(
      system, options.geometryInNewton, options.maxGeometryIterations, options.geometryTolerance,
      options.absoluteTolerance));
  return loops;
}

}  // namespace contactlab
