#include "core/io/VtkSeriesWriter.hpp"

#include "core/io/AtomicFile.hpp"
#include "core/io/VtuFile.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace contactlab {
namespace {

std::string xmlEscape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string fullPrecision(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

const char* byteOrder() {
  const std::uint16_t probe = 1;
  return *reinterpret_cast<const unsigned char*>(&probe) == 1 ? "LittleEndian" : "BigEndian";
}

// Describes the fields as the .pvtu must declare them; equal on all ranks or the .pvtu lies.
std::string fieldSignature(const MeshPiece& piece) {
  std::string signature;
  for (const auto& f : piece.pointData)
    signature += "point '" + f.name + "' " + std::to_string(f.components) + "; ";
  for (const auto& f : piece.cellData)
    signature += "cell '" + f.name + "' " + std::to_string(f.components) + "; ";
  return signature;
}

void broadcastString(std::string& text, int root, MPI_Comm comm) {
  unsigned long long length = text.size();
  MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, root, comm);
  text.resize(length);
  MPI_Bcast(text.data(), static_cast<int>(length), MPI_CHAR, root, comm);
}

// Collective: if any rank has an error, every rank throws the lowest failing rank's message,
// so that no rank goes on to a collective the others have left.
void throwIfAnyRankFailed(const std::string& localError, MPI_Comm comm) {
  int rank = 0;
  int size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  int failing = localError.empty() ? size : rank;
  MPI_Allreduce(MPI_IN_PLACE, &failing, 1, MPI_INT, MPI_MIN, comm);
  if (failing == size) return;
  std::string message = localError;
  broadcastString(message, failing, comm);
  if (size > 1) message += " (on rank " + std::to_string(failing) + ")";
  throw std::runtime_error(message);
}

template <class F>
std::string errorOf(F&& action) {
  try {
    action();
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

void writePDataArrays(std::ostream& out, const std::vector<FieldData>& fields) {
  for (const auto& f : fields)
    out << "      <PDataArray type=\"Float64\" Name=\"" << xmlEscape(f.name)
        << "\" NumberOfComponents=\"" << vtkComponents(f) << "\"/>\n";
}

}  // namespace

VtkSeriesWriter::VtkSeriesWriter(std::string directory, std::string baseName, MPI_Comm comm)
    : directory_(std::move(directory)), baseName_(std::move(baseName)), comm_(comm) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
}

std::string VtkSeriesWriter::pvdPath() const {
  return (std::filesystem::path(directory_) / (baseName_ + ".pvd")).string();
}

std::string VtkSeriesWriter::stepPath(int step) const {
  return (std::filesystem::path(directory_) / stepFileName(step)).string();
}

std::string VtkSeriesWriter::stepFileName(int step) const {
  char number[16];
  std::snprintf(number, sizeof number, "_%06d", step);
  return baseName_ + number + (size_ > 1 ? ".pvtu" : ".vtu");
}

std::string VtkSeriesWriter::pieceFileName(int step, int rank) const {
  char number[32];
  std::snprintf(number, sizeof number, "_%06d_p%d.vtu", step, rank);
  return baseName_ + number;
}

std::vector<std::string> VtkSeriesWriter::fileNames(int step) const {
  std::vector<std::string> names{stepFileName(step)};
  if (size_ > 1)
    for (int r = 0; r < size_; ++r)
      names.push_back(pieceFileName(step, r));
  names.push_back(baseName_ + ".pvd");
  return names;
}

void VtkSeriesWriter::writeStep(double time, const MeshPiece& piece) {
  const int step = numSteps();
  const std::string piecePath =
      size_ > 1 ? (std::filesystem::path(directory_) / pieceFileName(step, rank_)).string()
                : stepPath(step);

  // 1. Validate on every rank before any file of this step is touched.
  const std::string problem = std::isfinite(time)
                                  ? errorOf([&] { validateMeshPiece(piece); })
                                  : "time " + fullPrecision(time) + " is not finite";
  throwIfAnyRankFailed(
      problem.empty() ? problem : "cannot write results to '" + piecePath + "': " + problem, comm_);
  if (size_ > 1) {
    const std::string mine = fieldSignature(piece);
    std::string reference = mine;
    broadcastString(reference, 0, comm_);
    throwIfAnyRankFailed(mine == reference ? std::string()
                                           : "cannot write results to '" + stepPath(step) +
                                                 "': fields differ between ranks (rank 0: " +
                                                 reference + "this rank: " + mine + ")",
                         comm_);
  }

  // 2. Every rank writes its piece. 3. Only then rank 0 indexes the step in .pvtu and .pvd,
  // so that they never name a file that is not complete.
  throwIfAnyRankFailed(errorOf([&] { writeVtuFile(piecePath, piece); }), comm_);
  steps_.emplace_back(time, stepFileName(step));
  std::string error;
  if (rank_ == 0) {
    error = errorOf([&] {
      if (size_ > 1) writePvtu(step, piece);
      writePvd();
    });
  }
  try {
    throwIfAnyRankFailed(error, comm_);
  } catch (...) {
    steps_.pop_back();
    throw;
  }
}

void VtkSeriesWriter::writePvtu(int step, const MeshPiece& piece) const {
  writeFileAtomically(stepPath(step), [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"" << byteOrder()
        << "\" header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">\n"
        << "  <PUnstructuredGrid GhostLevel=\"0\">\n"
        << "    <PPointData>\n";
    writePDataArrays(out, piece.pointData);
    out << "    </PPointData>\n"
        << "    <PCellData>\n";
    writePDataArrays(out, piece.cellData);
    out << "    </PCellData>\n"
        << "    <PPoints>\n"
        << "      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
        << "    </PPoints>\n";
    for (int r = 0; r < size_; ++r)
      out << "    <Piece Source=\"" << xmlEscape(pieceFileName(step, r)) << "\"/>\n";
    out << "  </PUnstructuredGrid>\n"
        << "</VTKFile>\n";
  });
}

void VtkSeriesWriter::writePvd() const {
  writeFileAtomically(pvdPath(), [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"" << byteOrder() << "\">\n"
        << "  <Collection>\n";
    for (const auto& [time, file] : steps_)
      out << "    <DataSet timestep=\"" << fullPrecision(time) << "\" group=\"\" part=\"0\" file=\""
          << xmlEscape(file) << "\"/>\n";
    out << "  </Collection>\n"
        << "</VTKFile>\n";
  });
}

void VtkSeriesWriter::resume(int frames) {
  // The .pvd is this class's own output (writePvd): one DataSet line per frame.
  std::ifstream in(pvdPath());
  std::vector<std::pair<double, std::string>> steps;
  for (std::string line; std::getline(in, line) && static_cast<int>(steps.size()) < frames;) {
    const std::size_t time = line.find("timestep=\""), file = line.find("file=\"");
    if (time == std::string::npos || file == std::string::npos) continue;
    const std::size_t fileEnd = line.find('"', file + 6);
    std::string name = line.substr(file + 6, fileEnd - file - 6);
    for (const auto& [escaped, plain] : {std::pair<std::string, std::string>{"&quot;", "\""},
                                         {"&lt;", "<"},
                                         {"&gt;", ">"},
                                         {"&amp;", "&"}})
      for (std::size_t at; (at = name.find(escaped)) != std::string::npos;)
        name.replace(at, escaped.size(), plain);
    steps.emplace_back(std::stod(line.substr(time + 10)), name);
  }
  if (static_cast<int>(steps.size()) < frames)
    throw std::runtime_error(pvdPath() + ": " + std::to_string(steps.size()) +
                             " frames, the checkpoint counts " + std::to_string(frames));
  steps_ = std::move(steps);
  if (rank_ == 0) writePvd();
}

}  // namespace contactlab
