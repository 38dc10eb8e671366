#pragma once
// One MeshPiece as one VTK XML .vtu file; the building block of VtkSeriesWriter, usable alone
// for serial debugging output.
#include "core/io/MeshPiece.hpp"

#include <string>

namespace contactlab {

// Throws std::invalid_argument with one sentence describing the first inconsistency (sizes
// of points/offsets/connectivity/fields, node counts per cell type, point indices out of
// range, duplicate or empty field names).
void validateMeshPiece(const MeshPiece& piece);

// Number of components a field gets in VTK: 2D vectors (2 components) are padded to 3.
int vtkComponents(const FieldData& field);

// Validates and writes `piece` to `path` atomically: unstructured grid, Float64 points and
// fields, nodes reordered from gmsh to VTK, appended raw binary, zlib, UInt64 headers.
// Throws std::runtime_error "cannot write results to '<path>': <reason>".
void writeVtuFile(const std::string& path, const MeshPiece& piece);

}  // namespace contactlab
