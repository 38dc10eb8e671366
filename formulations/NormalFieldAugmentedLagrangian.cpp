#include "formulations/NormalFieldAugmentedLagrangian.hpp"

#include <stdexcept>

namespace contactlab {

NormalFieldAugmentedLagrangian::NormalFieldAugmentedLagrangian(double rn, double rt, double kappaN)
    : AugmentedLagrangian(rn, rt), kappaN_(kappaN) {
  if (!(kappaN >= 0))
    throw std::invalid_argument("the normal-field penalty kappa_n must be >= 0 (0: automatic)");
}

}  // namespace contactlab
