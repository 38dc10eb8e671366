#pragma once
// Time series of VTK XML files for ParaView: one .vtu per step on 1 rank, one .vtu piece per
// rank plus a .pvtu on several ranks, and a .pvd collection (rewritten after every step) that
// lists the steps with their times. All files are committed atomically (AtomicFile.hpp), and
// the .pvd only ever names steps whose files are complete.
#include "core/io/MeshPiece.hpp"

#include <mpi.h>

#include <string>
#include <utility>
#include <vector>

namespace contactlab {

class VtkSeriesWriter {
 public:
  // Files go to `directory` (created if needed) and are named after `baseName`:
  //   1 rank:  <base>_<step:06>.vtu
  //   P ranks: <base>_<step:06>_p<rank>.vtu (one per rank) + <base>_<step:06>.pvtu
  //   always:  <base>.pvd
  // Steps are numbered 0, 1, 2, ... in the order writeStep is called. An existing series of
  // the same name is overwritten. `comm` is used only inside writeStep (not duplicated).
  VtkSeriesWriter(std::string directory, std::string baseName, MPI_Comm comm);

  // Collective over the communicator. Writes this rank's piece (cells in gmsh node order are
  // reordered to VTK's, ElementType mapped to info(type).vtkType) with every field as Float64.
  // 2-component fields (2D vectors) are padded with a zero third component so that ParaView
  // treats them as vectors (Warp By Vector, glyphs). 6-component fields are shown by ParaView
  // as symmetric tensors in VTK's order xx, yy, zz, xy, yz, xz. All ranks must pass the same
  // field names and component counts in the same order.
  // Errors (invalid piece, I/O failure) on any rank throw std::runtime_error on every rank,
  // and the step is then not added to the .pvd.
  void writeStep(double time, const MeshPiece& piece);

  // Continues an existing series: keeps the first `frames` entries of the .pvd on disk (a run
  // continued from a checkpoint drops the frames written after it), so the next writeStep
  // appends frame `frames`. Every rank calls it. Throws std::runtime_error when the .pvd cannot be
  // read or has fewer frames.
  void resume(int frames);

  int numSteps() const { return static_cast<int>(steps_.size()); }
  // The names of the files writeStep(step) writes on every rank (the .vtu or .pvtu, each
  // rank's piece, the .pvd), in the directory.
  std::vector<std::string> fileNames(int step) const;
  std::string pvdPath() const;
  // Path of the file the .pvd names for `step` (.vtu on 1 rank, .pvtu on several).
  std::string stepPath(int step) const;

 private:
  std::string stepFileName(int step) const;
  std::string pieceFileName(int step, int rank) const;
  void writePvtu(int step, const MeshPiece& piece) const;
  void writePvd() const;

  std::string directory_;
  std::string baseName_;
  MPI_Comm comm_;
  int rank_ = 0;
  int size_ = 1;
  std::vector<std::pair<double, std::string>> steps_;  // time, file name relative to the .pvd
};

}  // namespace contactlab
