#pragma once
// Values read from a validated scene and checked against the model: vectors of the model's
// dimension, component lists, the mesh node nearest a point. Each throws InputError naming the
// scene (`where`) and the key's path.
#include "core/mesh/Mesh.hpp"

#include <Teuchos_ParameterList.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace contactlab {

// p's `key`, a list of dim (or 3, z = 0 in 2D) numbers.
std::array<double, 3> vector3(const Teuchos::ParameterList& p, const std::string& key,
                              const std::string& where, const std::string& path, int dim);

// Components: 'xyz' is "every component"; a z named on its own in 2D would act on nothing.
std::vector<int> componentList(const Teuchos::ParameterList& p, int dim, const std::string& where,
                               const std::string& path);

// The mesh node closest to `point` among those with usable[n] != 0 (every node when `usable`
// is empty), and its distance.
std::pair<std::int64_t, double> nearestNode(const Mesh& mesh, const std::array<double, 3>& point,
                                            const std::vector<char>& usable);

// "a, b, c".
std::string joinedNames(const std::vector<std::string>& names);

}  // namespace contactlab
