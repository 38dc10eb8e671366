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
  // How each block's elements form their strain (ElementTechnology.hpp): a registry name or
  // "automatic", by block name; a block without an entry is "automatic".
  std::map<std::string, std::string> elementTechnologies;
  std::vector<DirichletCondition> dirichlet;
  std::vector<SymmetryCondition> symmetries;
  // The symmetry planes normal to an axis, which resolveSymmetryConditions turns into Dirichlet
  // conditions: kept for what symmetry says beyond n . u = 0 (no friction across the plane).
  std::vector<SymmetryCondition> axisSymmetries;
  std::vector<SurfaceLoad> surfaceLoads;
  std::vector<BodyForce> bodyForces;
  std::vector<CentrifugalLoad> centrifugalLoads;
  std::vector<PointLoad> pointLoads;
  std::vector<NodalSpring> springs;
  std::vector<TieCondition> ties;
  // Prescribed block temperatures (at most one per block; a block without one stays at its
  // material's reference temperature). Only materials with a referenceTemperature() take one.
  std::vector<BlockTemperature> temperatures;
  // A 2D model of the solid of revolution about the y axis (x = r >= 0, y = z):
  // AxisymmetricKernel.hpp, AxisymmetricTotalLagrangianKernel.hpp. Every integral, load, reaction
  // and spring is then per full ring (a point load is a ring load: its force on the whole circle);
  // checkAxisymmetricModel.
  bool axisymmetric = false;
  // A 2D model of a plate of unit reference thickness loaded in its plane: sigma_zz = 0, each
  // block's law wrapped in PlaneStress (PlaneStress.hpp) by the Problem; every force is per unit
  // reference thickness; checkPlaneStressModel.
  bool planeStress = false;

  // Some block's material carries internal variables (plasticity): outputs add its fields.
  bool hasInternalVariables() const {
    for (const auto& [block, material] : materials)
      if (material->stateSize() > 0) return true;
    return false;
  }

  // The first pressure that follows the deformation (Follower: true, or automatic in a model
  // with a finite-strain block), nullptr if none: the 2D models whose current facets are not
  // known in full (the ring of an axisymmetric model, a plate's thickness) refuse it.
  const SurfaceLoad* followerPressure() const {
    bool finiteStrain = false;
    for (const auto& [block, material] : materials)
      finiteStrain |= material->kinematics() == Kinematics::FiniteStrain;
    for (const auto& load : surfaceLoads)
      if (load.kind == SurfaceLoad::Kind::Pressure &&
          (load.follower == SurfaceLoad::Follower::Yes ||
           (load.follower == SurfaceLoad::Follower::Automatic && finiteStrain)))
        return &load;
    return nullptr;
  }
};

}  // namespace contactlab
