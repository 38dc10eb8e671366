#include "core/materials/SimoMiehe.hpp"

#include "core/materials/ParameterCheck.hpp"
#include "core/materials/Tensor3.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace contactlab {
namespace {

using tensor3::Mat3;

constexpr const char* kLaw = "simo-miehe";

void require(bool ok, const std::string& what, double got) {
  requireParameter(kLaw, ok, what, got);
}

// (ln x - ln y) / (x - y) for x, y > 0, and its limit 1 / y at x = y. With u = (x - y) / y it is
// (ln(1 + u) / u) / y; below |u| = 1e-3 the series of ln(1 + u) / u (truncated after u^4: error
// below u^5 / 6 < 2e-16) replaces the quotient of two vanishing differences.
double logDividedDifference(double x, double y) {
  const double u = (x - y) / y;
  if (std::abs(u) < 1e-3)
    return (1.0 - u * (1.0 / 2.0 - u * (1.0 / 3.0 - u * (1.0 / 4.0 - u / 5.0)))) / y;
  return std::log1p(u) / u / y;
}

Mat3 fromVoigt(const double* v) {
  return {v[0], v[3], v[5], v[3], v[1], v[4], v[5], v[4], v[2]};
}

// The symmetric part of A in Voigt order xx yy zz xy yz xz.
void toVoigt(const Mat3& A, double* v) {
  v[0] = A[0];
  v[1] = A[4];
  v[2] = A[8];
  v[3] = 0.5 * (A[1] + A[3]);
  v[4] = 0.5 * (A[5] + A[7]);
  v[5] = 0.5 * (A[2] + A[6]);
}

void checkCurve(const SimoMiehe::Parameters& p) {
  const std::vector<double>& s = p.hardeningStrains;
  const std::vector<double>& t = p.hardeningStresses;
  require(p.isotropicHardening == 0.0,
          "give either Isotropic Hardening Modulus or a hardening curve (Hardening Strains and "
          "Hardening Stresses), not both",
          p.isotropicHardening);
  if (s.size() != t.size()) {
    std::ostringstream m;
    m << kLaw << ": Hardening Strains and Hardening Stresses must have the same number of "
      << "entries (got " << s.size() << " and " << t.size() << ")";
    throw std::invalid_argument(m.str());
  }
  require(s.size() >= 2, "Hardening Strains and Hardening Stresses need at least two points",
          static_cast<double>(s.size()));
  for (std::size_t i = 0; i < s.size(); ++i) {
    require(std::isfinite(s[i]), "Hardening Strains must be finite", s[i]);
    require(std::isfinite(t[i]), "Hardening Stresses must be finite", t[i]);
  }
  require(s[0] == 0.0, "Hardening Strains must start at 0 (the first point is the initial yield)",
          s[0]);
  std::ostringstream startStress;
  startStress << "Hardening Stresses must start at the Yield Stress " << p.yieldStress;
  require(t[0] == p.yieldStress, startStress.str(), t[0]);
  for (std::size_t i = 1; i < s.size(); ++i) {
    require(s[i] > s[i - 1],
            "Hardening Strains must increase strictly (entry " + std::to_string(i + 1) + ")", s[i]);
    require(t[i] >= t[i - 1],
            "Hardening Stresses must not decrease (entry " + std::to_string(i + 1) + ")", t[i]);
  }
}

}  // namespace

SimoMiehe::SimoMiehe(const Parameters& parameters) : parameters_(parameters) {
  const Parameters& p = parameters_;
  require(p.youngModulus > 0.0, "Young's modulus E must be > 0", p.youngModulus);
  require(p.poissonRatio > 0.0 && p.poissonRatio < 0.5, "Poisson's ratio nu must lie in (0, 0.5)",
          p.poissonRatio);
  require(p.yieldStress > 0.0, "Yield Stress must be > 0", p.yieldStress);
  require(p.isotropicHardening >= 0.0, "Isotropic Hardening Modulus must be >= 0",
          p.isotropicHardening);
  require(p.density >= 0.0, "density must be >= 0", p.density);
  if (p.hardeningStrains.empty() && p.hardeningStresses.empty()) {
    knotStrains_ = {0.0};
    knotStresses_ = {p.yieldStress};
    slopes_ = {p.isotropicHardening};
  } else {
    checkCurve(p);
    knotStrains_ = p.hardeningStrains;
    knotStresses_ = p.hardeningStresses;
    for (std::size_t i = 0; i + 1 < knotStrains_.size(); ++i)
      slopes_.push_back((knotStresses_[i + 1] - knotStresses_[i]) /
                        (knotStrains_[i + 1] - knotStrains_[i]));
    slopes_.push_back(slopes_.back());  // beyond the last point: the last segment's slope
  }
  const double E = p.youngModulus, nu = p.poissonRatio;
  K_ = E / (3.0 * (1.0 - 2.0 * nu));
  G_ = E / (2.0 * (1.0 + nu));
}

int SimoMiehe::segment(double alpha) const {
  const auto it = std::upper_bound(knotStrains_.begin(), knotStrains_.end(), alpha);
  return std::max(0, static_cast<int>(it - knotStrains_.begin()) - 1);
}

double SimoMiehe::yieldStress(double alpha) const {
  const int i = segment(alpha);
  return knotStresses_[i] + slopes_[i] * (alpha - knotStrains_[i]);
}

double SimoMiehe::hardeningSlope(double alpha) const {
  return slopes_[segment(alpha)];
}

void SimoMiehe::initializeState(double* state) const {
  const double identity[kStateSize] = {1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0};
  std::copy(identity, identity + kStateSize, state);
}

void SimoMiehe::evaluate(const MaterialInput& in, MaterialOutput& out) const {
  evaluateWithThermalStretch(
      parameters_.expansion, "simo-miehe", in, out,
      [this](const MaterialInput& i, MaterialOutput& o) { evaluateIsothermal(i, o); });
}

void SimoMiehe::evaluateIsothermal(const MaterialInput& in, MaterialOutput& out) const {
  using namespace tensor3;
  const double K = K_, G = G_;
  double state[kStateSize];
  std::copy(in.stateOld, in.stateOld + kStateSize, state);
  const auto fail = [&](const std::string& why) {
    out.P.fill(0.0);
    out.dPdF.fill(0.0);
    std::copy(state, state + kStateSize, out.stateNew);
    out.failed = true;
    out.failure = why;
  };

  const Mat3& F = in.F;
  const double detF = determinant(F);
  if (!(detF > 0.0) || !std::isfinite(detF)) {  // also a NaN or infinite F
    std::ostringstream s;
    s << kLaw << ": J = " << detF << (detF > 0.0 ? " is not finite" : " <= 0");
    return fail(s.str());
  }
  const Mat3 Finv = inverse(F, detF);
  const Mat3 Cpi = fromVoigt(state + kInversePlasticStrain);
  const Mat3 FCpi = multiply(F, Cpi);  // B = C_p^-1 F^T is its transpose
  const Mat3 be = multiplyTranspose(FCpi, F);

  // Principal frame of the trial b_e: b_a, columns of Q.
  std::array<double, 3> b;
  Mat3 Q;
  if (!symmetricEigen(be, b, Q) || !(std::min({b[0], b[1], b[2]}) > 0.0)) {
    std::ostringstream s;
    s << kLaw
      << ": the trial elastic left Cauchy-Green tensor is not positive definite (J = " << detF
      << ", equivalent plastic strain " << state[kEquivalentPlasticStrain] << ")";
    return fail(s.str());
  }

  // Trial logarithmic elastic strain and Kirchhoff stress, principal values.
  double eps[3], dev[3], tau[3], N[3] = {0.0, 0.0, 0.0};
  for (int a = 0; a < 3; ++a)
    eps[a] = 0.5 * std::log(b[a]);
  const double traceEps = eps[0] + eps[1] + eps[2];
  for (int a = 0; a < 3; ++a) {
    dev[a] = eps[a] - traceEps / 3.0;
    tau[a] = K * traceEps + 2.0 * G * dev[a];
  }
  const double devNorm = std::sqrt(dev[0] * dev[0] + dev[1] * dev[1] + dev[2] * dev[2]);
  const double qTrial = std::sqrt(1.5) * 2.0 * G * devNorm;
  double& alpha = state[kEquivalentPlasticStrain];
  const double yieldOld = yieldStress(alpha);

  // Tangent d tau / d eps_e trial = K I x I + 2 G c1 I_dev + c2 N x N (small-strain form).
  double c1 = 1.0, c2 = 0.0;
  if (qTrial - yieldOld > kYieldTolerance * yieldOld) {
    // Radial return: q trial - 3 G dgamma - sigma_y(alpha_n + dgamma) = 0 is linear on each
    // segment of the curve; walk the segments from alpha_n to the one holding the root.
    double dgamma = 0.0, H = 0.0;
    for (int i = segment(alpha);; ++i) {
      H = slopes_[i];
      dgamma = (qTrial - knotStresses_[i] - H * (alpha - knotStrains_[i])) / (3.0 * G + H);
      if (i + 1 == static_cast<int>(knotStrains_.size()) || alpha + dgamma <= knotStrains_[i + 1])
        break;
    }
    for (int a = 0; a < 3; ++a) {
      N[a] = dev[a] / devNorm;
      tau[a] -= 2.0 * G * std::sqrt(1.5) * dgamma * N[a];
      eps[a] -= std::sqrt(1.5) * dgamma * N[a];
    }
    c1 = 1.0 - 3.0 * G * dgamma / qTrial;
    c2 = 6.0 * G * G * (dgamma / qTrial - 1.0 / (3.0 * G + H));
    alpha += dgamma;
    // Exponential map: b_e = exp(2 eps_e) in the same frame, C_p^-1 = F^-1 b_e F^-T.
    const double beNewPrincipal[3] = {std::exp(2.0 * eps[0]), std::exp(2.0 * eps[1]),
                                      std::exp(2.0 * eps[2])};
    Mat3 beNew{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int a = 0; a < 3; ++a)
          beNew[i * 3 + j] += beNewPrincipal[a] * Q[i * 3 + a] * Q[j * 3 + a];
    toVoigt(multiplyTranspose(multiply(Finv, beNew), Finv), state + kInversePlasticStrain);
  }

  // tau = sum_a tau_a n_a n_a^T, P = tau F^-T.
  Mat3 kirchhoff{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int a = 0; a < 3; ++a)
        kirchhoff[i * 3 + j] += tau[a] * Q[i * 3 + a] * Q[j * 3 + a];
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J) {
      double s = 0.0;
      for (int j = 0; j < 3; ++j)
        s += kirchhoff[i * 3 + j] * Finv[J * 3 + j];
      out.P[i * 3 + J] = s;
    }

  // D = d tau / d b_e trial (minor symmetries), in the principal frame:
  //   D'_aacc = M_ac / (2 b_c),  M_ac = K + 2 G c1 (delta_ac - 1/3) + c2 N_a N_c;
  //   D'_abab = D'_abba = G c1 theta_ab / 2 (a != b), theta_ab = (ln b_a - ln b_b) / (b_a - b_b).
  // n_a (x) n_b: basis[(a * 3 + b) * 9 + i * 3 + j] = Q_ia Q_jb.
  double basis[81];
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          basis[(a * 3 + c) * 9 + i * 3 + j] = Q[i * 3 + a] * Q[j * 3 + c];
  double principal[3][3], shear[3][3];
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) {
      const double M = K + 2.0 * G * c1 * ((a == c ? 1.0 : 0.0) - 1.0 / 3.0) + c2 * N[a] * N[c];
      principal[a][c] = M / (2.0 * b[c]);
      shear[a][c] = a == c ? 0.0 : 0.5 * G * c1 * logDividedDifference(b[a], b[c]);
    }
  // D_ijkl = sum_ac principal_ac (n_a n_a)_ij (n_c n_c)_kl
  //        + sum_(a != c) shear_ac (n_a n_c)_ij ((n_a n_c)_kl + (n_a n_c)_lk);
  // (n_a n_c)_lk = (n_c n_a)_kl and shear_ac = shear_ca, so the second sum is over the pairs
  // a < c of shear_ac S_ij S_kl with S = n_a n_c + n_c n_a: 3 + 3 products per entry.
  constexpr int kPairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  double pairBasis[3][9];
  for (int p = 0; p < 3; ++p)
    for (int ij = 0; ij < 9; ++ij)
      pairBasis[p][ij] = basis[(kPairs[p][0] * 3 + kPairs[p][1]) * 9 + ij] +
                         basis[(kPairs[p][1] * 3 + kPairs[p][0]) * 9 + ij];
  double D[81];
  for (int ij = 0; ij < 9; ++ij) {
    double left[3], leftPair[3];
    for (int c = 0; c < 3; ++c) {
      left[c] = 0.0;
      for (int a = 0; a < 3; ++a)
        left[c] += principal[a][c] * basis[(a * 4) * 9 + ij];
    }
    for (int p = 0; p < 3; ++p)
      leftPair[p] = shear[kPairs[p][0]][kPairs[p][1]] * pairBasis[p][ij];
    for (int kl = 0; kl < 9; ++kl) {
      double d = 0.0;
      for (int c = 0; c < 3; ++c)
        d += left[c] * basis[(c * 4) * 9 + kl] + leftPair[c] * pairBasis[c][kl];
      D[ij * 9 + kl] = d;
    }
  }

  // d b_e_mn / dF_kL = delta_mk B_Ln + delta_nk B_Lm with B = C_p^-1 F^T, so
  // d tau_ij / dF_kL = 2 D_ijkn B_Ln; d (F^-T)_jJ / dF_kL = -F^-1_Jk F^-1_Lj. Then
  // dP_iJ / dF_kL = d tau_ij / dF_kL F^-1_Jj - F^-1_Jk P_iL.
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      for (int L = 0; L < 3; ++L) {
        double dTau[3];
        for (int j = 0; j < 3; ++j) {
          double s = 0.0;
          for (int n = 0; n < 3; ++n)
            s += D[(i * 3 + j) * 9 + k * 3 + n] * FCpi[n * 3 + L];
          dTau[j] = 2.0 * s;
        }
        for (int J = 0; J < 3; ++J) {
          double s = -Finv[J * 3 + k] * out.P[i * 3 + L];
          for (int j = 0; j < 3; ++j)
            s += dTau[j] * Finv[J * 3 + j];
          out.dPdF[(i * 3 + J) * 9 + k * 3 + L] = s;
        }
      }

  bool finite = true;
  for (double v : out.P)
    finite = finite && std::isfinite(v);
  for (double v : out.dPdF)
    finite = finite && std::isfinite(v);
  if (!finite) {
    std::copy(in.stateOld, in.stateOld + kStateSize, state);
    std::ostringstream s;
    s << kLaw << ": non-finite stress or tangent (J = " << detF << ")";
    return fail(s.str());
  }
  std::copy(state, state + kStateSize, out.stateNew);
}

}  // namespace contactlab
