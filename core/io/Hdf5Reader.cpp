#include "core/io/Hdf5Reader.hpp"

#include "base/InputError.hpp"

#include <filesystem>
#include <hdf5.h>

namespace contactlab {

Hdf5Reader::Hdf5Reader(std::string path) : path_(std::move(path)) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are thrown, not printed
  if (!std::filesystem::is_regular_file(path_)) throw InputError(path_ + ": no such file");
  if (H5Fis_hdf5(path_.c_str()) <= 0) throw InputError(path_ + ": not an HDF5 file");
  file_ = H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file_ < 0) throw InputError(path_ + ": cannot be opened for reading");
}

Hdf5Reader::~Hdf5Reader() {
  if (file_ >= 0) H5Fclose(file_);
}

void Hdf5Reader::fail(const std::string& what) const {
  throw InputError(path_ + ": " + what + " (not a contactlab checkpoint, or a damaged one)");
}

bool Hdf5Reader::hasDataset(const std::string& name) const {
  // Each level of the path must exist before the next is asked for.
  std::string prefix;
  for (std::size_t start = 0;;) {
    const std::size_t slash = name.find('/', start);
    prefix = name.substr(0, slash);
    if (H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    if (slash == std::string::npos) return true;
    start = slash + 1;
  }
}

std::size_t Hdf5Reader::datasetSize(const std::string& name) const {
  if (!hasDataset(name)) fail("no dataset '" + name + "'");
  const hid_t set = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
  if (set < 0) fail("cannot open dataset '" + name + "'");
  const hid_t space = H5Dget_space(set);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  H5Sclose(space);
  H5Dclose(set);
  if (n < 0) fail("cannot read the size of dataset '" + name + "'");
  return static_cast<std::size_t>(n);
}

void Hdf5Reader::readDataset(const std::string& name, std::int64_t type, void* data,
                             std::size_t size) const {
  if (size == 0) return;
  const hid_t set = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
  const bool ok = set >= 0 && H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0;
  if (set >= 0) H5Dclose(set);
  if (!ok) fail("cannot read dataset '" + name + "'");
}

std::vector<double> Hdf5Reader::doubles(const std::string& name) const {
  std::vector<double> values(datasetSize(name));
  readDataset(name, H5T_NATIVE_DOUBLE, values.data(), values.size());
  return values;
}

std::vector<std::int64_t> Hdf5Reader::integers(const std::string& name) const {
  std::vector<std::int64_t> values(datasetSize(name));
  readDataset(name, H5T_NATIVE_INT64, values.data(), values.size());
  return values;
}

namespace {

// The root group's attribute `name`, or -1 when it has none.
hid_t openAttribute(hid_t file, const std::string& name) {
  if (H5Aexists(file, name.c_str()) <= 0) return -1;
  return H5Aopen(file, name.c_str(), H5P_DEFAULT);
}

}  // namespace

void Hdf5Reader::readAttribute(const std::string& name, std::int64_t type, void* value) const {
  const hid_t attribute = openAttribute(file_, name);
  const bool ok = attribute >= 0 && H5Aread(attribute, type, value) >= 0;
  if (attribute >= 0) H5Aclose(attribute);
  if (!ok) fail("no attribute '" + name + "'");
}

double Hdf5Reader::doubleAttribute(const std::string& name) const {
  double value = 0;
  readAttribute(name, H5T_NATIVE_DOUBLE, &value);
  return value;
}

std::int64_t Hdf5Reader::integerAttribute(const std::string& name) const {
  std::int64_t value = 0;
  readAttribute(name, H5T_NATIVE_INT64, &value);
  return value;
}

std::string Hdf5Reader::stringAttribute(const std::string& name) const {
  const hid_t attribute = openAttribute(file_, name);
  if (attribute < 0) fail("no attribute '" + name + "'");
  const hid_t type = H5Aget_type(attribute);
  const std::size_t size = H5Tget_size(type);
  std::string value(size, '\0');
  const bool ok = H5Tget_class(type) == H5T_STRING && !H5Tis_variable_str(type) &&
                  H5Aread(attribute, type, value.data()) >= 0;
  H5Tclose(type);
  H5Aclose(attribute);
  if (!ok) fail("attribute '" + name + "' is not a string");
  return value.substr(0, value.find('\0'));
}

}  // namespace contactlab
