#pragma once
// Shared fixtures of the fem unit tests: element type lists, reference-cell sampling and small
// materials (the project's LinearElastic lives elsewhere; these keep the tests self-contained).
#include "core/fem/ReferenceElement.hpp"
#include "core/materials/Material.hpp"
#include "core/mesh/ElementType.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <string>
#include <vector>

namespace contactlab::test {

inline std::vector<ElementType> allTypes() {
  std::vector<ElementType> t;
  for (int k = 0; k <= static_cast<int>(ElementType::Hex27); ++k)
    t.push_back(static_cast<ElementType>(k));
  return t;
}

inline std::vector<ElementType> solidTypes() {
  std::vector<ElementType> t;
  for (ElementType type : allTypes())
    if (info(type).dim >= 2) t.push_back(type);
  return t;
}

inline std::vector<ElementType> planeTypes() {
  std::vector<ElementType> t;
  for (ElementType type : solidTypes())
    if (info(type).dim == 2) t.push_back(type);
  return t;
}

inline bool isSimplex(ElementType t) {
  return t == ElementType::Tri3 || t == ElementType::Tri6 || t == ElementType::Tet4 ||
         t == ElementType::Tet10;
}

inline double maxAbs(const std::vector<double>& v) {
  double m = 0;
  for (double e : v)
    m = std::max(m, std::abs(e));
  return m;
}

inline std::string nameOf(ElementType t) {
  return info(t).name;
}

// A point strictly inside the reference cell.
inline std::vector<double> randomPoint(ElementType type, std::mt19937& rng) {
  const int d = info(type).dim;
  std::uniform_real_distribution<double> u(0.02, 0.98);
  std::vector<double> xi(d);
  if (isSimplex(type)) {
    double sum;
    do {
      sum = 0;
      for (double& v : xi)
        v = u(rng), sum += v;
    } while (sum > 0.97);
  } else {
    for (double& v : xi)
      v = 2 * u(rng) - 1;
  }
  return xi;
}

// Physical nodes of a mildly curved element: the reference nodes through a smooth map
// x = A xi + c + eps * sin-terms (3 coordinates per node, z = 0 in 2D).
inline std::vector<double> distortedNodes(ElementType type, double eps = 0.05) {
  const auto& ref = ReferenceElement::get(type);
  const int d = ref.dim();
  const double A[3][3] = {{1.3, 0.2, -0.1}, {0.1, 0.9, 0.15}, {-0.05, 0.1, 1.1}};
  const double c[3] = {0.4, -0.7, 1.2};
  std::vector<double> x(3 * ref.numNodes(), 0.0);
  for (int a = 0; a < ref.numNodes(); ++a) {
    const double* xi = &ref.nodeCoordinates()[a * d];
    for (int i = 0; i < d; ++i) {
      double v = c[i];
      for (int j = 0; j < d; ++j)
        v += A[i][j] * xi[j];
      v += eps * std::sin(1.0 + xi[(i + 1) % d] * (i + 1.5));
      x[3 * a + i] = v;
    }
  }
  return x;
}

// distortedNodes of a 2D type moved to x in about [1.4, 4.4]: a cell of an axisymmetric model
// off its axis (x = r).
inline std::vector<double> ringNodes(ElementType type) {
  auto x = distortedNodes(type);
  for (std::size_t a = 0; a < x.size(); a += 3)
    x[a] += 2.5;
  return x;
}

// Isotropic linear elasticity, small strain.
class IsotropicElastic : public Material {
 public:
  IsotropicElastic(double E, double nu) {
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        C_[i * 6 + j] = lambda;
      C_[i * 6 + i] += 2 * mu;
      C_[(i + 3) * 6 + i + 3] = mu;
    }
  }
  std::string name() const override { return "test-isotropic"; }
  Kinematics kinematics() const override { return Kinematics::SmallStrain; }
  void evaluate(const MaterialInput& in, MaterialOutput& out) const override {
    for (int i = 0; i < 6; ++i) {
      out.stress[i] = 0;
      for (int j = 0; j < 6; ++j)
        out.stress[i] += C_[i * 6 + j] * in.strain[j];
    }
    out.tangent = C_;
  }
  const std::array<double, 36>& C() const { return C_; }

 private:
  std::array<double, 36> C_{};
};

// Saint Venant-Kirchhoff written out here, so that the kernels's tests do not depend on the
// materials module: S = lambda tr(E) I + 2 mu E, P = F S,
// dP_iJ/dF_kL = delta_ik S_JL + F_iI (lambda delta_IJ F_kL + mu (delta_IL F_kJ + delta_JL F_kI)).
class TestKirchhoff : public Material {
 public:
  TestKirchhoff(double lambda, double mu) : lambda_(lambda), mu_(mu) {}
  std::string name() const override { return "test-kirchhoff"; }
  Kinematics kinematics() const override { return Kinematics::FiniteStrain; }
  void evaluate(const MaterialInput& in, MaterialOutput& out) const override {
    const auto F = [&](int i, int J) { return in.F[i * 3 + J]; };
    double E[3][3], S[3][3], trE = 0;
    for (int I = 0; I < 3; ++I)
      for (int J = 0; J < 3; ++J) {
        double c = 0;
        for (int k = 0; k < 3; ++k)
          c += F(k, I) * F(k, J);
        E[I][J] = 0.5 * (c - (I == J));
      }
    for (int I = 0; I < 3; ++I)
      trE += E[I][I];
    for (int I = 0; I < 3; ++I)
      for (int J = 0; J < 3; ++J)
        S[I][J] = lambda_ * trE * (I == J) + 2 * mu_ * E[I][J];
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J) {
        double p = 0;
        for (int I = 0; I < 3; ++I)
          p += F(i, I) * S[I][J];
        out.P[i * 3 + J] = p;
        for (int k = 0; k < 3; ++k)
          for (int L = 0; L < 3; ++L) {
            double a = (i == k) * S[J][L];
            for (int I = 0; I < 3; ++I)
              a += F(i, I) *
                   (lambda_ * (I == J) * F(k, L) + mu_ * ((I == L) * F(k, J) + (J == L) * F(k, I)));
            out.dPdF[(i * 3 + J) * 9 + k * 3 + L] = a;
          }
      }
  }

 private:
  double lambda_, mu_;
};

// Nonlinear, unsymmetric law with one internal variable (a counter), to exercise the kernel's
// unsymmetric path and state handling: sigma = C eps + k (eps . eps) m + s eps_xx e_xy.
class UnsymmetricNonlinear : public IsotropicElastic {
 public:
  UnsymmetricNonlinear() : IsotropicElastic(100.0, 0.3) {}
  std::string name() const override { return "test-unsymmetric"; }
  int stateSize() const override { return 1; }
  void initializeState(double* state) const override { state[0] = 0; }
  void evaluate(const MaterialInput& in, MaterialOutput& out) const override {
    IsotropicElastic::evaluate(in, out);
    const double m[6] = {1, 0.5, -0.3, 0.2, 0.7, -0.4};
    double ee = 0;
    for (double e : in.strain)
      ee += e * e;
    for (int i = 0; i < 6; ++i) {
      out.stress[i] += kQuad * ee * m[i];
      for (int j = 0; j < 6; ++j)
        out.tangent[i * 6 + j] += kQuad * 2 * in.strain[j] * m[i];
    }
    out.stress[3] += kSkew * in.strain[0];
    out.tangent[3 * 6 + 0] += kSkew;
    if (out.stateNew) out.stateNew[0] = (in.stateOld ? in.stateOld[0] : 0) + 1;
  }

 private:
  static constexpr double kQuad = 500.0, kSkew = 30.0;
};

// Checks every column of the kernel's tangent K at u against central differences of its
// residual (step 1e-6, within 1e-6 of max |K|; gtest expectations labelled `label`); returns
// whether K is unsymmetric at that tolerance.
template <class Kernel, class Material>
bool expectTangentMatchesDifferences(const Kernel& kernel, const std::vector<double>& x,
                                     const std::vector<double>& u, const Material& material,
                                     const double* stateOld, double* stateNew,
                                     const std::vector<double>& K, const std::string& label) {
  const int nd = static_cast<int>(u.size());
  std::vector<double> fp(nd), fm(nd);
  const double h = 1e-6, scale = maxAbs(K);
  bool unsymmetric = false;
  for (int k = 0; k < nd; ++k) {
    auto up = u, um = u;
    up[k] += h, um[k] -= h;
    kernel.compute(x.data(), up.data(), material, stateOld, stateNew, fp.data(), nullptr);
    kernel.compute(x.data(), um.data(), material, stateOld, stateNew, fm.data(), nullptr);
    for (int i = 0; i < nd; ++i) {
      EXPECT_NEAR(K[i * nd + k], (fp[i] - fm[i]) / (2 * h), 1e-6 * scale)
          << label << " K(" << i << "," << k << ")";
      unsymmetric |= std::abs(K[i * nd + k] - K[k * nd + i]) > 1e-6 * scale;
    }
  }
  return unsymmetric;
}

// Expects the kernel's stress at every quadrature point, and its average, to be `expected`
// (6 Voigt components) within 1e-12.
template <class Kernel, class Material>
void expectUniformStress(const Kernel& kernel, const std::vector<double>& x,
                         const std::vector<double>& u, const Material& material,
                         const double* expected, const std::string& label) {
  std::vector<double> stress(6 * kernel.numQuadraturePoints());
  double average[6];
  kernel.stresses(x.data(), u.data(), material, nullptr, nullptr, stress.data(), average);
  for (int q = 0; q < kernel.numQuadraturePoints(); ++q)
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(stress[6 * q + k], expected[k], 1e-12) << label << " q=" << q;
  for (int k = 0; k < 6; ++k)
    EXPECT_NEAR(average[k], expected[k], 1e-12) << label;
}

// An element of `Kernel` on distortedNodes(t): x holds 3 coordinates per node, n nodes of d
// displacement components each.
template <class Kernel>
struct KernelElement {
  explicit KernelElement(ElementType t)
      : kernel(t), x(distortedNodes(t)), n(kernel.numNodes()), d(kernel.dim()) {}
  Kernel kernel;
  std::vector<double> x;
  int n, d;
  // u_a = G x_a + c (d components).
  std::vector<double> affineDisplacement(const double (&G)[3][3], const double* c) const {
    return displacement(G, c, false);
  }
  // u_a = (G - I) x_a + c: the deformation x -> G x + c.
  std::vector<double> affineDeformation(const double (&G)[3][3], const double* c) const {
    return displacement(G, c, true);
  }

 private:
  std::vector<double> displacement(const double (&G)[3][3], const double* c,
                                   bool minusPosition) const {
    std::vector<double> u(n * d);
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < d; ++i) {
        u[a * d + i] = minusPosition ? c[i] - x[3 * a + i] : c[i];
        for (int j = 0; j < d; ++j)
          u[a * d + i] += G[i][j] * x[3 * a + j];
      }
    return u;
  }
};

}  // namespace contactlab::test
