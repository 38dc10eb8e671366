#pragma once
// result.pvd and one .vtu (.pvtu + a piece per rank in parallel) per frame: first the rest
// frame at t = 0 (the undeformed state, written before step 1 so that an animation starts from
// rest), then one per converged step: the solid's fields and, with contact, the contact point
// data. Every frame has a point field node_id, each point's mesh node id (Mesh::nodeId: the
// gmsh node tag of a mesh file, index + 1 for a generated mesh; contact.csv's node column). A
// run that converges no step leaves the rest frame alone in the series.
#include "base/LinearAlgebra.hpp"
#include "core/io/OutputManifest.hpp"
#include "core/io/VtkSeriesWriter.hpp"
#include "core/problem/Problem.hpp"
#include "formulations/ContactProblem.hpp"

#include <memory>
#include <optional>
#include <string>

namespace contactlab {

class VtkSteps {
 public:
  // The files go to `folder`, each listed in its manifest before it is written.
  VtkSteps(OutputManifest& folder, MPI_Comm comm);

  // Collective. The rest frame at t = 0: zero displacement (so zero stresses), and with
  // contact the same point fields as a step's, all zero (every point free). Call once, before
  // the first step.
  void writeRest(const Problem& problem, const ContactProblem* contact);
  // Collective. u: the displacement at `time`; contact may be null. A run started from an
  // earlier state (Initial State) writes that state this way as its first frame, in place of
  // the rest frame.
  void write(double time, const Problem& problem, const ContactProblem* contact, const Vector& u);

  // Collective. A run continued from a checkpoint (--restart): the series keeps its first
  // `frames` frames, and the next write appends to it.
  void resume(int frames);
  // Frames written so far (the rest frame included).
  int frames() const { return series_ ? series_->numSteps() : 0; }

  // Empty until a frame was written.
  std::optional<std::string> pvdPath() const;

 private:
  void writeFrame(double time, MeshPiece piece, const Problem& problem);

  OutputManifest& folder_;
  const MPI_Comm comm_;
  std::unique_ptr<VtkSeriesWriter> series_;
};

}  // namespace contactlab
