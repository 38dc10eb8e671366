#include "core/mesh/MeshBroadcast.hpp"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace contactlab {
namespace {

// The mesh travels as one byte buffer: one size broadcast plus one payload broadcast, instead
// of a handful of messages per group.
class Writer {
 public:
  template <class T>
  void put(const T& value) {
    const auto* p = reinterpret_cast<const char*>(&value);
    bytes.insert(bytes.end(), p, p + sizeof(T));
  }
  template <class T>
  void putVector(const std::vector<T>& v) {
    put<std::uint64_t>(v.size());
    const auto* p = reinterpret_cast<const char*>(v.data());
    bytes.insert(bytes.end(), p, p + v.size() * sizeof(T));
  }
  void putString(const std::string& s) { putVector(std::vector<char>(s.begin(), s.end())); }
  std::vector<char> bytes;
};

class Reader {
 public:
  explicit Reader(const std::vector<char>& bytes) : bytes_(bytes) {}
  template <class T>
  T get() {
    T value;
    std::memcpy(&value, take(sizeof(T)), sizeof(T));
    return value;
  }
  template <class T>
  std::vector<T> getVector() {
    std::vector<T> v(get<std::uint64_t>());
    if (!v.empty()) std::memcpy(v.data(), take(v.size() * sizeof(T)), v.size() * sizeof(T));
    return v;
  }
  std::string getString() {
    auto v = getVector<char>();
    return std::string(v.begin(), v.end());
  }

 private:
  const char* take(std::size_t n) {
    if (pos_ + n > bytes_.size())
      throw std::runtime_error("broadcastMesh received a truncated mesh buffer");
    const char* p = bytes_.data() + pos_;
    pos_ += n;
    return p;
  }
  const std::vector<char>& bytes_;
  std::size_t pos_ = 0;
};

void putGroups(Writer& w, const std::vector<CellGroup>& groups) {
  w.put<std::uint64_t>(groups.size());
  for (const auto& g : groups) {
    w.putString(g.name);
    w.put<std::int32_t>(g.dim);
    w.put<std::int32_t>(static_cast<std::int32_t>(g.type));
    w.putVector(g.nodes);
    w.putVector(g.tags);
  }
}

std::vector<CellGroup> getGroups(Reader& r) {
  std::vector<CellGroup> groups(r.get<std::uint64_t>());
  for (auto& g : groups) {
    g.name = r.getString();
    g.dim = r.get<std::int32_t>();
    g.type = static_cast<ElementType>(r.get<std::int32_t>());
    g.nodes = r.getVector<std::int64_t>();
    g.tags = r.getVector<std::int64_t>();
  }
  return groups;
}

void check(int err, const char* what) {
  if (err != MPI_SUCCESS)
    throw std::runtime_error(std::string("broadcastMesh: MPI_Bcast of the mesh ") + what +
                             " failed with MPI error " + std::to_string(err));
}

}  // namespace

void broadcastMesh(Mesh& mesh, MPI_Comm comm, int root) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::vector<char> bytes;
  if (rank == root) {
    Writer w;
    w.put<std::int32_t>(mesh.dim);
    w.putString(mesh.source);
    w.putVector(mesh.coords);
    w.putVector(mesh.nodeTags);
    putGroups(w, mesh.blocks);
    putGroups(w, mesh.boundaries);
    bytes = std::move(w.bytes);
  }
  std::uint64_t size = bytes.size();
  check(MPI_Bcast(&size, 1, MPI_UINT64_T, root, comm), "size");
  bytes.resize(size);
  // MPI counts are int: send large meshes in chunks.
  for (std::uint64_t offset = 0; offset < size; offset += INT_MAX) {
    const int count = static_cast<int>(std::min<std::uint64_t>(INT_MAX, size - offset));
    check(MPI_Bcast(bytes.data() + offset, count, MPI_CHAR, root, comm), "data");
  }
  if (rank == root) return;
  Reader r(bytes);
  Mesh copy;
  copy.dim = r.get<std::int32_t>();
  copy.source = r.getString();
  copy.coords = r.getVector<double>();
  copy.nodeTags = r.getVector<std::int64_t>();
  copy.blocks = getGroups(r);
  copy.boundaries = getGroups(r);
  mesh = std::move(copy);
}

}  // namespace contactlab
