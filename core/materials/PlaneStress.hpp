#pragma once
// Plane stress from any 3D law: the out-of-plane component (eps_zz in small strain, the stretch
// F_zz in finite strain) is an unknown of the quadrature point, solved by a local Newton loop so
// that sigma_zz = 0 (P_zz = 0), and the tangent is condensed onto the other components,
// C_ab - C_az C_zb / C_zz (the same with dP/dF). A 2D kernel gives this law the plane-strain
// input (eps_zz = 0, F_zz = 1) and reads back the in-plane stress and tangent as it does for
// plane strain; MaterialOutput::outOfPlane carries the solved value (a finite-strain kernel
// needs J = det F_2D F_zz for the Cauchy stress).
//
// Why a wrapper and not per-law formulas: the laws with internal variables (J2, Simo-Miehe)
// have no closed plane-stress form, and a wrapper keeps each law one 3D class. The local loop
// starts from the plane-strain state at every evaluation (no extra internal variable), which is
// exact in one step for linear elasticity and takes a few steps for the others.
#include "core/materials/Material.hpp"

#include <memory>

namespace contactlab {

class PlaneStress : public Material {
 public:
  // Throws std::invalid_argument for an empty law.
  explicit PlaneStress(std::shared_ptr<const Material> law);

  std::string name() const override { return law_->name() + " in plane stress"; }
  Kinematics kinematics() const override { return law_->kinematics(); }
  int stateSize() const override { return law_->stateSize(); }
  void initializeState(double* state) const override { law_->initializeState(state); }
  // Sets `failed` when the local loop does not make sigma_zz vanish within its iterations, or
  // when the law's out-of-plane stiffness is not positive there.
  void evaluate(const MaterialInput& in, MaterialOutput& out) const override;
  double density() const override { return law_->density(); }
  bool symmetricTangent() const override { return law_->symmetricTangent(); }
  // A linear law stays linear: sigma = (C condensed) eps.
  bool linear() const override { return law_->linear(); }
  bool isochoricFlow() const override { return law_->isochoricFlow(); }
  double equivalentPlasticStrain(const double* state) const override {
    return law_->equivalentPlasticStrain(state);
  }
  std::optional<double> referenceTemperature() const override {
    return law_->referenceTemperature();
  }
  const Material& law() const { return *law_; }

 private:
  std::shared_ptr<const Material> law_;
};

}  // namespace contactlab
