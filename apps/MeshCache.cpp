#include "apps/MeshCache.hpp"

namespace contactlab {

std::shared_ptr<Mesh> MeshCache::meshFor(const std::string& key,
                                         const std::function<std::shared_ptr<Mesh>()>& build) {
  for (auto it = kept_.begin(); it != kept_.end(); ++it)
    if (it->first == key) {
      kept_.splice(kept_.begin(), kept_, it);
      return std::make_shared<Mesh>(*kept_.front().second);
    }
  std::shared_ptr<Mesh> mesh = build();
  ++builds_;
  if (capacity_ == 0) return mesh;
  kept_.emplace_front(key, std::make_shared<const Mesh>(*mesh));
  while (kept_.size() > capacity_)
    kept_.pop_back();
  return mesh;
}

}  // namespace contactlab
