#include "apps/output/VtkSteps.hpp"

#include <utility>

namespace contactlab {

VtkSteps::VtkSteps(std::string folder, MPI_Comm comm) : folder_(std::move(folder)), comm_(comm) {}

void VtkSteps::write(double time, const Problem& problem, const ContactProblem* contact,
                     const Vector& u) {
  if (!series_) series_ = std::make_unique<VtkSeriesWriter>(folder_, "result", comm_);
  MeshPiece piece = problem.outputPiece(u);
  if (contact) contact->addPointData(piece);
  series_->writeStep(time, piece);
}

std::optional<std::string> VtkSteps::pvdPath() const {
  if (!series_) return std::nullopt;
  return series_->pvdPath();
}

}  // namespace contactlab
