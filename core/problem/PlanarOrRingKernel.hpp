#pragma once
// An element technology's kernel written twice: per dimension D for plane-strain and 3D cells
// (on the plain kernels' products, SmallStrainProducts.hpp / FiniteStrainProducts.hpp), and once
// for the axisymmetric ring, whose hoop row the ring products or the run-time SlotOperator
// carry. Derived declares
//   template <int D> void evaluatePlanar(ARGS) const;   void evaluateRing(ARGS) const;
// (ARGS those of ElementKernel::evaluate), befriends this class and instantiates it in its
// source file (template class PlanarOrRingKernel<Derived>;); evaluate() calls the one the cell
// needs.
#include "core/problem/ElementKernel.hpp"

namespace contactlab {

template <class Derived>
class PlanarOrRingKernel : public ElementKernel {
 protected:
  using ElementKernel::ElementKernel;

  void evaluate(const double* x, const double* u, const Material& material, const double* stateOld,
                double* stateNew, double* residual, double* tangent, double* pointStress,
                double* averageStress, const std::optional<double>& temperature) const override {
    const Derived& kernel = static_cast<const Derived&>(*this);
    if (axisymmetric_)
      kernel.evaluateRing(x, u, material, stateOld, stateNew, residual, tangent, pointStress,
                          averageStress, temperature);
    else if (dim_ == 2)
      kernel.template evaluatePlanar<2>(x, u, material, stateOld, stateNew, residual, tangent,
                                        pointStress, averageStress, temperature);
    else
      kernel.template evaluatePlanar<3>(x, u, material, stateOld, stateNew, residual, tangent,
                                        pointStress, averageStress, temperature);
  }
};

}  // namespace contactlab
