#pragma once
// Small-strain solid element: internal force f = int B^T sigma dV and tangent K = int B^T C B dV
// for 3D cells and 2D plane strain (Voigt rows {0, 1, 3} of Material.hpp), through the products of
// SmallStrainProducts.hpp. Conventions of ElementKernel.hpp.
#include "core/problem/DimensionTemplatedKernel.hpp"

namespace contactlab {

class SmallStrainKernel : public DimensionTemplatedKernel<SmallStrainKernel> {
 public:
  explicit SmallStrainKernel(ElementType type, int quadratureDegree = -1)
      : DimensionTemplatedKernel(type, quadratureDegree) {}

  Kinematics kinematics() const override { return Kinematics::SmallStrain; }

 private:
  friend class DimensionTemplatedKernel<SmallStrainKernel>;
  template <int D>
  void evaluateIn(const double* x, const double* u, const Material& material,
                  const double* stateOld, double* stateNew, double* residual, double* tangent,
                  double* pointStress, double* averageStress,
                  const std::optional<double>& temperature) const;
};

}  // namespace contactlab
