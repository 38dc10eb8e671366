#pragma once
// An ElementKernel written once as a template over the spatial dimension D: Derived declares
//   template <int D> void evaluateIn(x, u, material, stateOld, stateNew, residual, tangent,
//                                    pointStress, averageStress, temperature) const
// (the arguments of ElementKernel::evaluate), befriends this class, and instantiates it in its
// source file (template class DimensionTemplatedKernel<Derived>;), where evaluateIn is defined;
// evaluate() then calls evaluateIn<2> or evaluateIn<3> by dim().
#include "core/problem/ElementKernel.hpp"

namespace contactlab {

template <class Derived>
class DimensionTemplatedKernel : public ElementKernel {
 protected:
  using ElementKernel::ElementKernel;

  void evaluate(const double* x, const double* u, const Material& material, const double* stateOld,
                double* stateNew, double* residual, double* tangent, double* pointStress,
                double* averageStress, const std::optional<double>& temperature) const override;
};

template <class Derived>
void DimensionTemplatedKernel<Derived>::evaluate(const double* x, const double* u,
                                                 const Material& material, const double* stateOld,
                                                 double* stateNew, double* residual,
                                                 double* tangent, double* pointStress,
                                                 double* averageStress,
                                                 const std::optional<double>& temperature) const {
  const Derived& kernel = static_cast<const Derived&>(*this);
  if (dim_ == 2)
    kernel.template evaluateIn<2>(x, u, material, stateOld, stateNew, residual, tangent,
                                  pointStress, averageStress, temperature);
  else
    kernel.template evaluateIn<3>(x, u, material, stateOld, stateNew, residual, tangent,
                                  pointStress, averageStress, temperature);
}

}  // namespace contactlab
