#pragma once
// A small HDF5 file writer for files a user reads with any HDF5 tool (h5dump, h5py): named
// one- or two-dimensional datasets of doubles or 64-bit integers, and scalar attributes on
// the root group. Serial HDF5 C API: the caller gathers the data to one rank. The file is
// written under a temporary name beside `path` and renamed into place by commit()
// (AtomicFile.hpp), so a crash mid-write leaves the previous file whole.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace contactlab {

class Hdf5Writer {
 public:
  // Creates the temporary file (and the parent directories). Throws std::runtime_error
  // naming `path` when it cannot.
  explicit Hdf5Writer(std::string path);
  // Without commit(), the temporary is removed and `path` keeps its old content.
  ~Hdf5Writer();
  Hdf5Writer(const Hdf5Writer&) = delete;
  Hdf5Writer& operator=(const Hdf5Writer&) = delete;

  // A dataset `name` ("group/name": groups are created) of values.size() / columns rows.
  // `units`, when given, becomes the dataset's string attribute "units".
  void writeDoubles(const std::string& name, const std::vector<double>& values,
                    std::size_t columns = 1, const std::string& units = "");
  void writeIntegers(const std::string& name, const std::vector<std::int64_t>& values,
                     std::size_t columns = 1);
  // Scalar attributes of the root group.
  void writeAttribute(const std::string& name, double value);
  void writeAttribute(const std::string& name, std::int64_t value);
  void writeAttribute(const std::string& name, const std::string& value);

  // Closes the file and renames it onto `path`.
  void commit();

 private:
  void writeDataset(const std::string& name, std::int64_t type, const void* data, std::size_t size,
                    std::size_t columns);
  void close() noexcept;

  std::string path_, temporary_;
  std::int64_t file_ = -1;  // hid_t (kept out of this header: only Hdf5Writer.cpp includes hdf5.h)
  bool committed_ = false;
};

}  // namespace contactlab
