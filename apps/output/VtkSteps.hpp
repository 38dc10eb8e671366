#pragma once
// result.pvd and one .vtu (.pvtu + a piece per rank in parallel) per converged step: the
// solid's fields and, with contact, the contact point data. The series starts at the first
// converged step, so a run that converges none leaves no result.pvd behind.
#include "base/LinearAlgebra.hpp"
#include "core/io/VtkSeriesWriter.hpp"
#include "core/problem/Problem.hpp"
#include "formulations/ContactProblem.hpp"

#include <memory>
#include <optional>
#include <string>

namespace contactlab {

class VtkSteps {
 public:
  VtkSteps(std::string folder, MPI_Comm comm);

  // Collective. u: the displacement at `time`; contact may be null.
  void write(double time, const Problem& problem, const ContactProblem* contact, const Vector& u);

  // Empty until a step was written.
  std::optional<std::string> pvdPath() const;

 private:
  const std::string folder_;
  const MPI_Comm comm_;
  std::unique_ptr<VtkSeriesWriter> series_;
};

}  // namespace contactlab
