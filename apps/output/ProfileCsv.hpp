#pragma once
// The scene's profiles (Output/Profiles): a field read at the mesh nodes nearest evenly spaced
// points of a segment, in Cartesian or cylindrical components, as one CSV per call (the last
// converged step's profile_<name>.csv, a stage's profile_<name>_t<time>.csv).
#include "apps/SceneModel.hpp"
#include "core/io/OutputManifest.hpp"
#include "core/problem/Problem.hpp"

#include <string>

namespace contactlab {

class ProfileCsv {
 public:
  ProfileCsv(const SceneModel& sm, const Problem& problem);

  // Every profile at displacement u, converged at time t, into the folder's
  // profile_<name><suffix>.csv (listed in its manifest). Collective (a node's values come from
  // the ranks holding it); rank 0 writes.
  void write(OutputManifest& folder, const std::string& suffix, const Vector& u, double t) const;

 private:
  const SceneModel& sm_;
  const Problem& problem_;
};

}  // namespace contactlab
