#include "core/io/VtuFile.hpp"

#include "core/io/AtomicFile.hpp"
#include "core/io/VtkNodeOrder.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <set>
#include <stdexcept>

namespace contactlab {
namespace {

void invalid(const std::string& what) {
  throw std::invalid_argument(what);
}

void validateFields(const std::vector<FieldData>& fields, std::size_t count, const char* kind,
                    std::set<std::string>& names) {
  for (const auto& f : fields) {
    if (f.name.empty()) invalid(std::string("a ") + kind + " field has an empty name");
    if (!names.insert(std::string(kind) + f.name).second)
      invalid(std::string(kind) + " field '" + f.name + "' is given twice");
    if (f.components < 1)
      invalid(std::string(kind) + " field '" + f.name + "' has " + std::to_string(f.components) +
              " components");
    const std::size_t expected = count * static_cast<std::size_t>(f.components);
    if (f.values.size() != expected)
      invalid(std::string(kind) + " field '" + f.name + "' has " + std::to_string(f.values.size()) +
              " values, expected " + std::to_string(expected));
  }
}

vtkNew<vtkDoubleArray> toVtkArray(const FieldData& field, std::size_t tuples) {
  vtkNew<vtkDoubleArray> array;
  array->SetName(field.name.c_str());
  const int out = vtkComponents(field);
  array->SetNumberOfComponents(out);
  array->SetNumberOfTuples(static_cast<vtkIdType>(tuples));
  double* dst = array->GetPointer(0);
  for (std::size_t t = 0; t < tuples; ++t)
    for (int c = 0; c < out; ++c)
      dst[t * out + c] = c < field.components ? field.values[t * field.components + c] : 0.0;
  return array;
}

vtkNew<vtkUnstructuredGrid> toVtkGrid(const MeshPiece& piece) {
  vtkNew<vtkUnstructuredGrid> grid;

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(piece.numPoints()));
  std::copy(piece.points.begin(), piece.points.end(),
            vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0));
  grid->SetPoints(points);

  const std::size_t numCells = piece.numCells();
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  vtkNew<vtkUnsignedCharArray> types;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(numCells + 1));
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(numCells ? piece.offsets.back() : 0));
  types->SetNumberOfValues(static_cast<vtkIdType>(numCells));
  offsets->SetValue(0, 0);
  for (std::size_t c = 0; c < numCells; ++c) {
    const auto begin = piece.offsets[c];
    const auto& order = vtkNodeOrder(piece.cellTypes[c]);
    for (std::size_t i = 0; i < order.size(); ++i)
      connectivity->SetValue(begin + i, piece.connectivity[begin + order[i]]);
    offsets->SetValue(c + 1, piece.offsets[c + 1]);
    types->SetValue(c, static_cast<unsigned char>(info(piece.cellTypes[c]).vtkType));
  }
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  grid->SetCells(types, cells);

  for (const auto& f : piece.pointData)
    grid->GetPointData()->AddArray(toVtkArray(f, piece.numPoints()));
  for (const auto& f : piece.cellData)
    grid->GetCellData()->AddArray(toVtkArray(f, numCells));
  return grid;
}

}  // namespace

int vtkComponents(const FieldData& field) {
  return field.components == 2 ? 3 : field.components;
}

void validateMeshPiece(const MeshPiece& piece) {
  if (piece.points.size() % 3 != 0)
    invalid("points has " + std::to_string(piece.points.size()) +
            " coordinates, not a multiple of 3");
  const std::size_t numCells = piece.numCells();
  const std::size_t numPoints = piece.numPoints();
  // An empty piece may leave offsets empty; otherwise offsets bracket every cell.
  if (!(numCells == 0 && piece.offsets.empty()) && piece.offsets.size() != numCells + 1)
    invalid("offsets has " + std::to_string(piece.offsets.size()) + " entries for " +
            std::to_string(numCells) + " cells, expected " + std::to_string(numCells + 1));
  if (!piece.offsets.empty() && piece.offsets.front() != 0) invalid("offsets[0] is not 0");
  for (std::size_t c = 0; c < numCells; ++c) {
    const ElementTypeInfo& type = info(piece.cellTypes[c]);
    if (piece.offsets[c + 1] - piece.offsets[c] != type.nodes)
      invalid("cell " + std::to_string(c) + " (" + type.name + ") has " +
              std::to_string(piece.offsets[c + 1] - piece.offsets[c]) + " nodes, expected " +
              std::to_string(type.nodes));
  }
  const std::size_t used = numCells ? static_cast<std::size_t>(piece.offsets.back()) : 0;
  if (piece.connectivity.size() != used)
    invalid("connectivity has " + std::to_string(piece.connectivity.size()) +
            " entries, offsets use " + std::to_string(used));
  for (const auto p : piece.connectivity)
    if (p < 0 || static_cast<std::size_t>(p) >= numPoints)
      invalid("connectivity refers to point " + std::to_string(p) + " of " +
              std::to_string(numPoints));
  std::set<std::string> names;
  validateFields(piece.pointData, numPoints, "point", names);
  validateFields(piece.cellData, numCells, "cell", names);
}

void writeVtuFile(const std::string& path, const MeshPiece& piece) {
  try {
    validateMeshPiece(piece);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error("cannot write results to '" + path + "': " + e.what());
  }
  vtkNew<vtkUnstructuredGrid> grid = toVtkGrid(piece);

  const std::string temporary = temporaryPathFor(path);
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  writer->SetFileName(temporary.c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();  // raw binary: smallest and fastest to read
  writer->SetCompressorTypeToZLib();
  writer->SetHeaderTypeToUInt64();  // pieces above 4 GiB stay valid
  errno = 0;
  if (writer->Write() != 1) {
    // vtkErrorCode's enum is header-only; its string lookup would need another VTK library.
    const auto code = writer->GetErrorCode();
    const std::string reason = code == vtkErrorCode::OutOfDiskSpaceError ? std::strerror(ENOSPC)
                               : errno != 0                              ? std::strerror(errno)
                                            : "VTK writer error code " + std::to_string(code);
    discardFile(temporary);
    throw std::runtime_error("cannot write results to '" + path + "': " + reason);
  }
  commitFile(temporary, path);
}

}  // namespace contactlab
