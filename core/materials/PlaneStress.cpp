#include "core/materials/PlaneStress.hpp"

#include "base/NumberText.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace contactlab {
namespace {

constexpr int kMaxIterations = 30;
// The loop stops when the Newton update of the out-of-plane unknown is below this fraction of
// the point's deformation (the in-plane strain, or F - I): sigma_zz is then ~1e-10 of the
// stresses, below what the global Newton tolerance (1e-8 of the first residual) sees, and above
// the round-off of a law whose own return map converges to ~1e-12.
constexpr double kRelativeTolerance = 1e-10;

// Schur complement of the unknown's row and column z in the n x n row-major matrix A; the row
// and column z are then zero (sigma_zz is held at 0 whatever the strain).
template <int n>
void condense(double* A, int z) {
  const double pivot = A[z * n + z];
  for (int a = 0; a < n; ++a) {
    if (a == z) continue;
    const double factor = A[a * n + z] / pivot;
    if (factor == 0.0) continue;
    for (int b = 0; b < n; ++b)
      if (b != z) A[a * n + b] -= factor * A[z * n + b];
  }
  for (int k = 0; k < n; ++k)
    A[z * n + k] = A[k * n + z] = 0.0;
}

}  // namespace

PlaneStress::PlaneStress(std::shared_ptr<const Material> law) : law_(std::move(law)) {
  if (!law_) throw std::invalid_argument("plane stress needs a material law");
}

void PlaneStress::evaluate(const MaterialInput& in, MaterialOutput& out) const {
  const bool small = law_->kinematics() == Kinematics::SmallStrain;
  MaterialInput local = in;
  // The unknown and the deformation it is measured against (the in-plane strain, or F - I).
  double z = small ? in.strain[2] : in.F[8];
  double scale = 0.0;
  if (small) {
    for (int k : {0, 1, 3})
      scale = std::max(scale, std::abs(in.strain[k]));
  } else {
    for (int k : {0, 1, 3, 4})
      scale = std::max(scale, std::abs(in.F[k] - (k == 0 || k == 4 ? 1.0 : 0.0)));
  }
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    (small ? local.strain[2] : local.F[8]) = z;
    law_->evaluate(local, out);
    if (out.failed) {
      out.failure = "plane stress: " + out.failure;
      return;
    }
    const double stress = small ? out.stress[2] : out.P[8];
    const double stiffness = small ? out.tangent[2 * 6 + 2] : out.dPdF[8 * 9 + 8];
    if (!(stiffness > 0)) {
      out.failed = true;
      out.failure = "plane stress: the out-of-plane stiffness is " + numberText(stiffness) +
                    " at " + (small ? "eps_zz = " : "F_zz = ") + numberText(z) +
                    " (not > 0): no thickness change can make sigma_zz vanish";
      return;
    }
    const double step = -stress / stiffness;
    // Measured against the deformation (F - I for a stretch near 1), with a floor of a few
    // ulps of z, below which round-off moves it.
    const double tolerance = small ? kRelativeTolerance * std::max(scale, std::abs(z))
                                   : std::max(kRelativeTolerance * std::max(scale, std::abs(z - 1)),
                                              1e-15 * std::abs(z));
    if (std::abs(step) <= tolerance) {
      if (small) {
        out.stress[2] = 0.0;
        condense<6>(out.tangent.data(), 2);
      } else {
        out.P[8] = 0.0;
        condense<9>(out.dPdF.data(), 8);
      }
      out.outOfPlane = z;
      return;
    }
    // A stretch stays positive: halve the way to zero rather than step past it.
    z = small || z + step > 0 ? z + step : 0.5 * z;
  }
  out.failed = true;
  out.failure = "plane stress: sigma_zz did not vanish in " + std::to_string(kMaxIterations) +
                " local iterations (last " + (small ? "eps_zz = " : "F_zz = ") + numberText(z) +
                ")";
}

}  // namespace contactlab
