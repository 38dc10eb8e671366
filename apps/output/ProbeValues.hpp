#pragma once
// The scene's probes (Output/Probes): the displacement or stress at the mesh node nearest each
// named point, for summary.json. Recorded after each converged step, so the summary holds the
// last converged step's values, also when a later step fails.
#include "apps/SceneModel.hpp"
#include "core/io/JsonWriter.hpp"
#include "core/problem/Problem.hpp"

namespace contactlab {

class ProbeValues {
 public:
  ProbeValues(const SceneModel& sm, const Problem& problem);

  // The values at displacement u, converged at time t (the stresses take the block
  // temperatures of t). Collective (a node's values come from the rank owning it).
  void record(const Vector& u, double t);

  // {name: {field, point, node, distance, value}}, in the scene's order.
  const JsonValue& json() const { return probes_; }

 private:
  const SceneModel& sm_;
  const Problem& problem_;
  JsonValue probes_ = JsonValue::object();
};

}  // namespace contactlab
