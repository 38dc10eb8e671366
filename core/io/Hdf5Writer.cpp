#include "core/io/Hdf5Writer.hpp"

#include "core/io/AtomicFile.hpp"

#include <hdf5.h>
#include <stdexcept>

namespace contactlab {
namespace {

// HDF5 prints its own error stack by default; a thrown exception says it instead.
void silenceHdf5() {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

}  // namespace

Hdf5Writer::Hdf5Writer(std::string path) : path_(std::move(path)) {
  silenceHdf5();
  temporary_ = temporaryPathFor(path_);
  file_ = H5Fcreate(temporary_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) throw std::runtime_error("cannot write results to '" + path_ + "'");
}

Hdf5Writer::~Hdf5Writer() {
  close();
  if (!committed_) discardFile(temporary_);
}

void Hdf5Writer::close() noexcept {
  if (file_ >= 0) H5Fclose(file_);
  file_ = -1;
}

void Hdf5Writer::writeDataset(const std::string& name, std::int64_t type, const void* data,
                              std::size_t size, std::size_t columns) {
  const hsize_t dims[2] = {columns ? size / columns : 0, columns};
  const hid_t space = H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr);
  const hid_t links = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(links, 1);
  const hid_t set = H5Dcreate2(file_, name.c_str(), type, space, links, H5P_DEFAULT, H5P_DEFAULT);
  const bool ok =
      set >= 0 && (size == 0 || H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0);
  if (set >= 0) H5Dclose(set);
  H5Pclose(links);
  H5Sclose(space);
  if (!ok) throw std::runtime_error("cannot write results to '" + path_ + "': dataset " + name);
}

void Hdf5Writer::writeDoubles(const std::string& name, const std::vector<double>& values,
                              std::size_t columns, const std::string& units) {
  writeDataset(name, H5T_NATIVE_DOUBLE, values.data(), values.size(), columns);
  if (units.empty()) return;
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, units.size());
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attribute = H5Acreate_by_name(file_, name.c_str(), "units", type, space, H5P_DEFAULT,
                                            H5P_DEFAULT, H5P_DEFAULT);
  const bool ok = attribute >= 0 && H5Awrite(attribute, type, units.c_str()) >= 0;
  if (attribute >= 0) H5Aclose(attribute);
  H5Sclose(space);
  H5Tclose(type);
  if (!ok) throw std::runtime_error("cannot write results to '" + path_ + "': units of " + name);
}

void Hdf5Writer::writeIntegers(const std::string& name, const std::vector<std::int64_t>& values,
                               std::size_t columns) {
  writeDataset(name, H5T_NATIVE_INT64, values.data(), values.size(), columns);
}

namespace {

void writeScalarAttribute(hid_t file, const std::string& path, const std::string& name, hid_t type,
                          const void* value) {
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attribute = H5Acreate2(file, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  const bool ok = attribute >= 0 && H5Awrite(attribute, type, value) >= 0;
  if (attribute >= 0) H5Aclose(attribute);
  H5Sclose(space);
  if (!ok) throw std::runtime_error("cannot write results to '" + path + "': attribute " + name);
}

}  // namespace

void Hdf5Writer::writeAttribute(const std::string& name, double value) {
  writeScalarAttribute(file_, path_, name, H5T_NATIVE_DOUBLE, &value);
}

void Hdf5Writer::writeAttribute(const std::string& name, std::int64_t value) {
  writeScalarAttribute(file_, path_, name, H5T_NATIVE_INT64, &value);
}

void Hdf5Writer::writeAttribute(const std::string& name, const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.empty() ? 1 : value.size());
  try {
    writeScalarAttribute(file_, path_, name, type, value.empty() ? "" : value.c_str());
  } catch (...) {
    H5Tclose(type);
    throw;
  }
  H5Tclose(type);
}

void Hdf5Writer::commit() {
  if (H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0)
    throw std::runtime_error("cannot write results to '" + path_ + "'");
  close();
  commitFile(temporary_, path_);
  committed_ = true;
}

}  // namespace contactlab
