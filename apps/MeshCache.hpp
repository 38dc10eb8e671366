#pragma once
// The meshes a process keeps from one run to the next (`contactlab batch`): a study's runs
// mostly share the mesh, and generating it with gmsh is a fifth of a small 2D run's time in the
// batch process (measured on hertz-2d by perf). A run gets a copy (it adds its own point
// groups to its mesh), built again only when its Mesh section differs.
#include "core/mesh/Mesh.hpp"

#include <functional>
#include <list>
#include <memory>
#include <string>
#include <utility>

namespace contactlab {

class MeshCache {
 public:
  // At most `capacity` meshes are kept, the least recently used dropped first.
  explicit MeshCache(std::size_t capacity = 2) : capacity_(capacity) {}

  // A copy of the mesh kept under `key`, or the mesh `build` returns (kept under `key`; an
  // exception from `build` keeps nothing).
  std::shared_ptr<Mesh> meshFor(const std::string& key,
                                const std::function<std::shared_ptr<Mesh>()>& build);
  std::size_t size() const { return kept_.size(); }
  int builds() const { return builds_; }

 private:
  std::size_t capacity_;
  int builds_ = 0;
  std::list<std::pair<std::string, std::shared_ptr<const Mesh>>> kept_;  // newest first
};

}  // namespace contactlab
