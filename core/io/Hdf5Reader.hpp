#pragma once
// Reads what Hdf5Writer wrote: named datasets of doubles or 64-bit integers (flattened, row
// by row) and the root group's scalar attributes. Every rank may open the same file: reading
// needs no communication. Errors throw InputError naming the file and the missing or unreadable
// item: a file given by the user (a checkpoint) is input.
#include <cstdint>
#include <string>
#include <vector>

namespace contactlab {

class Hdf5Reader {
 public:
  // Throws InputError when `path` does not exist or is not an HDF5 file.
  explicit Hdf5Reader(std::string path);
  ~Hdf5Reader();
  Hdf5Reader(const Hdf5Reader&) = delete;
  Hdf5Reader& operator=(const Hdf5Reader&) = delete;

  const std::string& path() const { return path_; }
  bool hasDataset(const std::string& name) const;
  std::vector<double> doubles(const std::string& name) const;
  std::vector<std::int64_t> integers(const std::string& name) const;
  double doubleAttribute(const std::string& name) const;
  std::int64_t integerAttribute(const std::string& name) const;
  std::string stringAttribute(const std::string& name) const;

 private:
  void readDataset(const std::string& name, std::int64_t type, void* data, std::size_t size) const;
  void readAttribute(const std::string& name, std::int64_t type, void* value) const;
  std::size_t datasetSize(const std::string& name) const;
  [[noreturn]] void fail(const std::string& what) const;

  std::string path_;
  std::int64_t file_ = -1;  // hid_t
};

}  // namespace contactlab
