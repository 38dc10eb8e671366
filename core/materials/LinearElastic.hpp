#pragma once
// Isotropic linear elasticity, small strain: sigma = lambda tr(eps) I + 2 mu eps.
// Plane strain is this law with the out-of-plane strains zero (see Material.hpp).
#include "core/materials/Material.hpp"

namespace contactlab {

class LinearElastic : public Material {
 public:
  // Throws std::invalid_argument when E <= 0 or nu is outside (-1, 0.5).
  LinearElastic(double youngModulus, double poissonRatio, double density = 0.0);

  std::string name() const override { return "linear-elastic"; }
  Kinematics kinematics() const override { return Kinematics::SmallStrain; }
  void evaluate(const MaterialInput& in, MaterialOutput& out) const override;
  double density() const override { return density_; }

  double youngModulus() const { return E_; }
  double poissonRatio() const { return nu_; }

 private:
  const double E_, nu_, density_;
  std::array<double, 36> C_{};
};

}  // namespace contactlab
