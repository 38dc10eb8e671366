#include "apps/SceneTemperatures.hpp"

#include "apps/SceneLoadFunction.hpp"
#include "base/InputError.hpp"

#include <cmath>

namespace contactlab {

std::vector<BlockTemperature> blockTemperatures(const Teuchos::ParameterList& section,
                                                const SolidModel& model, double endTime,
                                                const std::string& where) {
  std::vector<BlockTemperature> temperatures;
  for (auto it = section.begin(); it != section.end(); ++it) {
    const std::string& block = section.name(it);
    const std::string path = "Temperature/" + block;
    const auto material = model.materials.find(block);
    if (material == model.materials.end()) {
      std::string blocks;
      for (const auto& [name, law] : model.materials)
        blocks += (blocks.empty() ? "" : ", ") + name;
      throw InputError(where + ": " + path + ": '" + block +
                       "' is not a block of Materials (blocks: " + blocks + ")");
    }
    if (!material->second->referenceTemperature())
      throw InputError(where + ": " + path + ": the block's material '" + material->second->name() +
                       "' takes no temperature (it has no thermal strain)");
    const Teuchos::ParameterList& t = section.sublist(block);
    BlockTemperature temperature;
    temperature.block = block;
    temperature.value = t.get<double>("Value");
    if (!std::isfinite(temperature.value))
      throw InputError(where + ": " + path + "/Value must be a finite number");
    temperature.function = loadFunction(t, endTime, where, path);
    temperatures.push_back(temperature);
  }
  return temperatures;
}

}  // namespace contactlab
