#include "apps/output/VtkSteps.hpp"

#include <algorithm>

namespace contactlab {

VtkSteps::VtkSteps(OutputManifest& folder, MPI_Comm comm) : folder_(folder), comm_(comm) {}

void VtkSteps::writeRest(const Problem& problem, const ContactProblem* contact) {
  const auto u = problem.createVector();
  u->putScalar(0.0);
  MeshPiece piece = problem.outputPiece(*u, 0.0);  // the rest frame is the state at t = 0
  if (contact) {
    // The contact fields a step writes, by the contact problem's own list, zeroed: the state
    // left by the initial pairing is not a converged one.
    const std::size_t solidFields = piece.pointData.size();
    contact->addPointData(piece);
    for (std::size_t f = solidFields; f < piece.pointData.size(); ++f)
      std::fill(piece.pointData[f].values.begin(), piece.pointData[f].values.end(), 0.0);
  }
  writeFrame(0.0, std::move(piece), problem);
}

void VtkSteps::write(double time, const Problem& problem, const ContactProblem* contact,
                     const Vector& u) {
  MeshPiece piece = problem.outputPiece(u, time);
  if (contact) contact->addPointData(piece);
  writeFrame(time, std::move(piece), problem);
}

void VtkSteps::writeFrame(double time, MeshPiece piece, const Problem& problem) {
  const Mesh& mesh = *problem.model().mesh;
  FieldData ids{"node_id", 1, {}};
  for (std::int64_t node : problem.dofs().overlapNodes())
    ids.values.push_back(static_cast<double>(mesh.nodeId(node)));
  piece.pointData.push_back(std::move(ids));
  if (!series_) series_ = std::make_unique<VtkSeriesWriter>(folder_.folder(), "result", comm_);
  // Listed by rank 0 before writeStep's first collective, so before any rank writes.
  folder_.add(series_->fileNames(series_->numSteps()));
  series_->writeStep(time, piece);
}

std::optional<std::string> VtkSteps::pvdPath() const {
  if (!series_) return std::nullopt;
  return series_->pvdPath();
}

void VtkSteps::resume(int frames) {
  series_ = std::make_unique<VtkSeriesWriter>(folder_.folder(), "result", comm_);
  series_->resume(frames);
}

}  // namespace contactlab
