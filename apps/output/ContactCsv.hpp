#pragma once
// contact.csv (doc/scenes.md "The output folder"): one row per contact point of the last converged
// step, named by its slave node's id (Mesh::nodeId: the gmsh node tag of a mesh file, index + 1 for
// a generated mesh), with its current coordinates and its reference ones beside them
// (reference_x..z: comparing with a reference solution needs no nearest-node match), gap (empty
// where the point found no master), pressure, tangential traction, slip and status. Rewritten after
// each converged step (atomically, by rank 0).
#include "core/mesh/Mesh.hpp"
#include "formulations/ContactProblem.hpp"
#include "formulations/ContactZone.hpp"

#include <string>
#include <vector>

namespace contactlab {

class ContactCsv {
 public:
  explicit ContactCsv(std::string path);

  // The points of `contact` in its present state; call on rank 0 only (the results are
  // gathered there).
  void write(const ContactProblem& contact, const std::vector<ContactZone>& zones,
             const Mesh& mesh) const;

 private:
  const std::string path_;
};

}  // namespace contactlab
