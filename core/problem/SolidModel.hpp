#pragma once
// Everything that defines a solid model independently of how it is solved: the mesh, one
// material per element block, boundary conditions, springs to ground and loads. (A regularizing
// inertia is the algorithm's: NonlinearSystem::setInertia.)
#include "core/materials/Material.hpp"
#include "core/mesh/Mesh.hpp"
#include "core/problem/Loads.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace contactlab {

struct SolidModel {
  std::shared_ptr<const Mesh> mesh;
  std::map<std::string, std::shared_ptr<const Material>> materials;  // by block name
  std::vector<DirichletCondition> dirichlet;
  std::vector<SymmetryCondition> symmetries;
  std::vector<SurfaceLoad> surfaceLoads;
  std::vector<BodyForce> bodyForces;
  std::vector<CentrifugalLoad> centrifugalLoads;
  std::vector<PointLoad> pointLoads;
  std::vector<NodalSpring> springs;

  // Some block's material carries internal variables (plasticity): outputs add its fields.
  bool hasInternalVariables() const {
    for (const auto& [block, material] : materials)
      if (material->stateSize() > 0) return true;
    return false;
  }
};

}  // namespace contactlab
