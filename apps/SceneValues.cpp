#include "apps/SceneValues.hpp"

#include "base/InputError.hpp"

#include <cmath>
#include <limits>

namespace contactlab {

using Teuchos::ParameterList;

std::array<double, 3> vector3(const ParameterList& p, const std::string& key,
                              const std::string& where, const std::string& path, int dim) {
  const auto& v = p.get<Teuchos::Array<double>>(key);
  if (static_cast<int>(v.size()) != dim && static_cast<int>(v.size()) != 3)
    throw InputError(where + ": " + path + "/" + key + " must have " + std::to_string(dim) +
                     " components");
  // A 2D model has no z: a z component that is not zero would be dropped without a word.
  if (dim == 2 && v.size() == 3 && v[2] != 0.0)
    throw InputError(where + ": " + path + "/" + key + " has a z component (" +
                     std::to_string(v[2]) + ") in a 2D model: give 2 components, or z = 0");
  std::array<double, 3> out{};
  for (int i = 0; i < dim; ++i)
    out[i] = v[i];
  return out;
}

std::vector<int> componentList(const ParameterList& p, int dim, const std::string& where,
                               const std::string& path) {
  const std::string components = p.get<std::string>("Components");
  if (dim == 2 && components != "xyz" && components.find('z') != std::string::npos)
    throw InputError(where + ": " + path + "/Components: '" + components +
                     "' names z in a 2D model, which has x and y only");
  std::vector<int> list;
  for (char c : components)
    if (c - 'x' < dim) list.push_back(c - 'x');
  return list;
}

std::pair<std::int64_t, double> nearestNode(const Mesh& mesh, const std::array<double, 3>& point,
                                            const std::vector<char>& usable) {
  double best = std::numeric_limits<double>::max();
  std::int64_t node = -1;
  for (std::size_t n = 0; n < mesh.numNodes(); ++n) {
    if (!usable.empty() && !usable[n]) continue;
    double d2 = 0;
    for (int i = 0; i < 3; ++i)
      d2 += std::pow(mesh.coords[3 * n + i] - point[i], 2);
    if (d2 < best) best = d2, node = static_cast<std::int64_t>(n);
  }
  return {node, std::sqrt(best)};
}

std::string joinedNames(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names)
    s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace contactlab
