#pragma once
// Contact law at one contact point: the pointwise part of a formulation (penalty, exact
// Lagrange multipliers, augmented Lagrangian), independent of how the point was discretized.
//
// The discretization (node-to-segment, rigid obstacle) supplies the point's kinematic
// variables k = (g, v_1 .. v_nt) and their linear operators B on the element dofs:
//   g   gap along the master normal n, positive when the surfaces are apart;
//   v   slip increment of the slave point relative to the master since the last converged step,
//       in the tangent basis (t_1, t_2), nt = dim - 1 components (none when mu = 0).
// Formulations with multipliers add m = (p, Lambda_1 .. Lambda_nt) at the point:
//   p       contact pressure (>= 0 in compression),
//   Lambda  the seed's normalized tangential multiplier, ||Lambda|| <= 1 (slip direction).
// The law returns the residual coefficients r = (r_k, r_m) and their Jacobian J = dr/d(k, m),
// all already multiplied by the point's weight w (tributary area). The element residual is
// R_u = sum_i r_k[i] B_i and R_m = r_m; the tangent is B^T J_kk B, B^T J_km, J_mk B, J_mm.
//
// Relation to the seed's notation (doc/theory.md): d_n = -g, lambda_n = -p, lambda-hat_n =
// -p-hat, and the seed's weak forms F = 0 are our residuals with R_u = -(F_cont + F_frot)
// (R_u = f_int - f_ext + contact), R_p = F~_cont, R_Lambda = F~_frot.
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace contactlab {

constexpr int kMaxLawVariables = 6;  // (g, v1, v2, p, Lambda1, Lambda2)

// Contact status of a point, as written to the results (contact_status).
enum class ContactStatus { Free = 0, Stick = 1, Slip = 2 };

struct LawInput {
  double weight = 0.0;  // tributary area w of the point
  double mu = 0.0;      // friction coefficient
  int nt = 0;           // tangential components in use (0 when mu == 0)
  double gap = 0.0;
  std::array<double, 2> slip{};  // slip increment v
  double p = 0.0;                // multipliers (ignored by laws without them)
  std::array<double, 2> Lambda{};
  // History of laws that carry one (penalty: tangential resistance at the last converged step,
  // in the current tangent basis).
  std::array<double, 2> tangentialOld{};
  // The seam for the algorithms: a status or friction threshold frozen by a fixed-point loop.
  // frozenStatus < 0 lets the status follow the iterate (Newton); 0 free, 1 stick, 2 slip, 3
  // closed with the friction status following the iterate, 4 slip at its onset (kSlipOnset,
  // BallProjection.hpp). frozenThreshold < 0 lets the
  // friction threshold mu * pressure follow it.
  int frozenStatus = -1;
  double frozenThreshold = -1.0;
  // Local scale of the formulation's coefficients (c_n, c_t or r_n, r_t), set by the automatic
  // cycling treatment; 1 elsewhere. Laws whose coefficients are part of the model (penalty)
  // ignore it.
  double coefficientScale = 1.0;
  // The zone's contact stiffness E / h (pressure per length; 0: unknown), which turns the
  // multiplier rows' residuals into forces (LawOutput::normalRowForce).
  double stiffnessScale = 0.0;
};

struct LawOutput {
  std::array<double, kMaxLawVariables> r{};
  std::array<double, kMaxLawVariables * kMaxLawVariables> J{};  // row major, n x n, n = size()
  ContactStatus status = ContactStatus::Free;
  double pressure = 0.0;                       // contact pressure transmitted (>= 0)
  std::array<double, 2> tangentialTraction{};  // on the slave, tangent basis (opposes slip)
  double threshold = 0.0;                      // friction threshold in use (mu * pressure-like)
  // The quantity whose sign decides the natural contact status, whatever is frozen: closed
  // when >= 0 (augmented pressure p^ = p - c g; penalty: -eps_n g).
  double indicator = 0.0;
  // Where the friction status switches, for a closed point: slip when > 0 ((|x| - rho) / rho of
  // the law's projection on its friction ball); 0 without friction.
  double frictionIndicator = 0.0;
  // A closed point whose friction threshold is round-off (frictionThresholdIsRoundoff): it
  // transmits no friction, so it neither sticks nor slips, whatever status the algorithms use
  // (the results write it as closed without friction).
  bool frictionlessClosed = false;
  // The factors that make the multiplier rows' residuals forces (laws with multipliers; 0
  // otherwise), for ContactPoint::constraintResidual: the normal row (w g closed: times the
  // contact stiffness LawInput::stiffnessScale; (w / c) p open: times c) and the friction rows
  // (w c_t v at stick: times the stiffness over c_t; a direction error w dLambda at slip: times
  // the threshold). The rows themselves are lengths and numbers, whose norm next to the forces'
  // does not see a violation: a stick point may have slipped without friction while its rows
  // stay far below a force target (code_aster SSNV128; doc/algorithms.md "Three non-smooth
  // things, one loop each").
  double normalRowForce = 0.0;
  double frictionRowForce = 0.0;
};

// Friction thresholds at or below the pressure of a penetration of kTouchingGap times the
// point's size are a touching point's, not a pressure: the round-off of its gap, or the margin
// `Initial Contact` seeds (ContactProblem::seedInitialStatuses, a tenth of this). Such a point
// carries no friction. Its multiplier Lambda (a direction scaled by 1 / threshold) would
// otherwise enter the tangent through a column of size w * threshold only, and a Newton update
// could put an arbitrarily large value into Lambda (a mortar point whose weighted gap is a
// round-off below 0). The cut must sit near the gap's round-off (~1e-16 of the coordinates,
// times the sums of a mortar row), not above it: its pressure c 1e-12 h grows with the
// coefficient, and a larger cut puts the whole contact pressure of a strongly augmented zone
// below it, which then slides without friction. 1e-12 h keeps four decades above round-off and
// cuts a real pressure only beyond c ~ 1e11 E/h.
constexpr double kTouchingGap = 1e-12;
inline bool frictionThresholdIsRoundoff(double threshold, const LawInput& in,
                                        double normalCoefficient) {
  // The point's size: w is a length in 2D (nt = 1) and an area in 3D.
  const double size = in.nt == 2 ? std::sqrt(in.weight) : in.weight;
  return !(threshold > kTouchingGap * in.mu * normalCoefficient * size);
}

class ContactLaw {
 public:
  virtual ~ContactLaw() = default;
  virtual std::string name() const = 0;
  // Whether the point carries multiplier unknowns (p and, with friction, Lambda).
  virtual bool hasMultipliers() const = 0;
  // Number of law variables: kinematic (1 + nt) plus multipliers (1 + nt, if any).
  int size(int nt) const { return (1 + nt) * (hasMultipliers() ? 2 : 1); }
  // The unknowns the formulation gives each contact point in a dim-dimensional problem, which
  // the layout of the system's unknowns reserves: the multipliers (p, Lambda) the law evaluates,
  // then any of the formulation's own that the kernel handles (the normal field's n_s).
  virtual int pointUnknowns(int nt, int /*dim*/) const { return hasMultipliers() ? 1 + nt : 0; }
  // Their names for the outputs (contact.csv's unknown_<name> columns, the VTK point fields),
  // pointUnknowns(nt, dim) of them in layout order: "p", "lambda_1".. for the multipliers.
  virtual std::vector<std::string> pointUnknownNames(int nt, int /*dim*/) const {
    std::vector<std::string> names;
    if (!hasMultipliers()) return names;
    names.push_back("p");
    for (int k = 1; k <= nt; ++k)
      names.push_back("lambda_" + std::to_string(k));
    return names;
  }
  // Normal-field formulations: the point's last dim unknowns are a slave normal n_s, which the
  // gap is measured along, tied to the master normal n(u) by the equation
  // w kappa_n (n_s - n(u)) = 0 (ContactPointKernel). kappa_n for a point of the given size
  // (its tributary length, or the root of its area); only called when hasNormalField().
  virtual bool hasNormalField() const { return false; }
  virtual double normalFieldPenalty(double /*size*/) const { return 0.0; }
  virtual void evaluate(const LawInput& in, LawOutput& out) const = 0;
  // The normal coefficient (c_n, r_n or eps_n) before any local scaling.
  virtual double normalCoefficient() const = 0;
  // Whether the coefficients change the solution (penalty) rather than only the path to it;
  // the automatic cycling treatment, which adapts them, is refused for such laws.
  virtual bool coefficientsChangeSolution() const { return false; }
  // Whether the coefficients enter the forces of a status (augmented Lagrangian, penalty),
  // rather than only choosing the status (Lagrange): what the automatic cycling treatment, which
  // scales them, relies on.
  virtual bool coefficientsEnterForces() const { return true; }
  // Whether J is symmetric for a point with nt friction components, whatever its status (with
  // the kinematics' B, the point's tangent B^T J B is then symmetric too): the linear solver
  // may then take the assembled tangent as symmetric.
  virtual bool symmetricJacobian(int nt) const = 0;
};

}  // namespace contactlab
