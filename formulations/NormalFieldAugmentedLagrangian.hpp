#pragma once
// The seed's non-standard augmented Lagrangian ("Lagrangien augmente non standard",
// doc/theory.md): the slave normals are unknowns. At each contact point a vector n_s joins the
// multipliers (p, Lambda); the gap is measured along it, g = n_s . (self x_s - sum_a N_a x_a), and
// the kinematic condition n_s = n(u), n(u) the master's normal at the point's master point in the
// current configuration, is the equation
//   R_ns = w kappa_n (n_s - n(u)) = 0        (seed: int [n_s - n(u)] kappa_n dn_s* = 0).
// The pointwise law on (g, v, p, Lambda) is the augmented Lagrangian's, unchanged; the kernel
// (ContactPointKernel) adds the n_s columns (dg/dn_s = x_s - x_m) and the R_ns rows, whose
// derivative -w kappa_n dn/du it takes in closed form where the discretization has one, else by
// central differences of n(u) (ContactPointKernel::normalFieldColumns).
//
// Choices the seed leaves open, made here:
// - the friction plane is the pairing's (its tangents t_k, from the master normal), not n_s's:
//   at a solution n_s = n(u), the same plane;
// - the seed's equilibrium term int [n_s - n(u)] kappa_n dn is not added: it vanishes wherever
//   the kinematic condition holds, so the solutions are the same, and without it the residual
//   keeps the standard form;
// - kappa_n = 0 (the default) is automatic: r_n times the point's size (a pressure, of the
//   order of E when r_n ~ E/h), which keeps the R_ns rows on the scale of the force rows.
// At a converged state the normal field equals the master's normal, so the solution is the
// augmented Lagrangian's with the same geometry; what changes is the Newton path: within a
// pairing the normal follows the iterate through kappa_n instead of staying frozen.
#include "formulations/AugmentedLagrangian.hpp"

namespace contactlab {

class NormalFieldAugmentedLagrangian : public AugmentedLagrangian {
 public:
  // rn, rt > 0 as AugmentedLagrangian; kappaN >= 0 (0: automatic).
  NormalFieldAugmentedLagrangian(double rn, double rt, double kappaN);
  std::string name() const override { return "normal-field-augmented-lagrangian"; }
  int pointUnknowns(int nt, int dim) const override { return 1 + nt + dim; }
  // The multipliers', then the slave normal's components normal_x, normal_y(, normal_z).
  std::vector<std::string> pointUnknownNames(int nt, int dim) const override {
    auto names = AugmentedLagrangian::pointUnknownNames(nt, dim);
    for (int c = 0; c < dim; ++c)
      names.push_back(std::string("normal_") + "xyz"[c]);
    return names;
  }
  bool hasNormalField() const override { return true; }
  double normalFieldPenalty(double size) const override {
    return kappaN_ > 0 ? kappaN_ : normalCoefficient() * size;
  }
  // The n_s columns of the equilibrium rows (p^ dB/dn_s) have no transposed counterpart.
  bool symmetricJacobian(int /*nt*/) const override { return false; }

 private:
  double kappaN_;
};

}  // namespace contactlab
