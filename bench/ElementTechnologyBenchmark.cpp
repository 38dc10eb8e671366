// Benchmark: the cost of one element evaluation (residual and tangent) per element technology,
// against full integration of the same cell and law. J2 small strain (E = 200, nu = 0.3, yield
// 0.2, hardening 20) in a state where every point flows plastically (strains about 1 %), on a
// distorted cell; the finite-strain technologies with Simo-Miehe alike. Prints a Markdown table:
// cell, technology, microseconds per evaluation (best of five batches) and the ratio to full
// integration.
//
//   bench_element_technology [--evaluations N] [--cell quad4|hex8|ring]
#include "core/fem/ReferenceElement.hpp"
#include "core/materials/J2SmallStrain.hpp"
#include "core/materials/SimoMiehe.hpp"
#include "core/problem/FBarKernel.hpp"
#include "core/problem/ProjectedDilatationKernel.hpp"
#include "core/problem/ProjectedJacobianKernel.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

using namespace contactlab;

namespace {

// The reference cell under an affine map and a smooth distortion (as the unit tests' cells).
std::vector<double> distortedCell(ElementType type, bool ring) {
  const auto& ref = ReferenceElement::get(type);
  const int d = ref.dim();
  const double A[3][3] = {{1.3, 0.2, -0.1}, {0.1, 0.9, 0.15}, {-0.05, 0.1, 1.1}};
  std::vector<double> x(3 * ref.numNodes(), 0.0);
  for (int a = 0; a < ref.numNodes(); ++a) {
    const double* xi = &ref.nodeCoordinates()[a * d];
    for (int i = 0; i < d; ++i) {
      double v = 0.5;
      for (int j = 0; j < d; ++j)
        v += A[i][j] * xi[j];
      x[3 * a + i] =
          v + 0.05 * std::sin(1.0 + xi[(i + 1) % d] * (i + 1.5)) + (ring && i == 0 ? 2.0 : 0.0);
    }
  }
  return x;
}

// Microseconds per compute() of `kernel`, the best of five batches of `evaluations`.
double microseconds(const ElementKernel& kernel, const Material& law, ElementType type, bool ring,
                    int evaluations) {
  const auto x = distortedCell(type, ring);
  const int nd = kernel.numDofs();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> r(-0.02, 0.02);
  std::vector<double> u(nd);
  for (double& v : u)
    v = r(rng);
  std::vector<double> stateOld(kernel.numQuadraturePoints() * law.stateSize()),
      stateNew(stateOld.size()), f(nd), K(nd * nd);
  if (!stateOld.empty()) kernel.initializeState(law, stateOld.data());
  double best = 1e300;
  for (int batch = 0; batch < 5; ++batch) {
    const auto start = std::chrono::steady_clock::now();
    for (int e = 0; e < evaluations; ++e) {
      std::fill(f.begin(), f.end(), 0.0);
      std::fill(K.begin(), K.end(), 0.0);
      kernel.compute(x.data(), u.data(), law, stateOld.data(), stateNew.data(), f.data(), K.data());
    }
    const std::chrono::duration<double, std::micro> t = std::chrono::steady_clock::now() - start;
    best = std::min(best, t.count() / evaluations);
  }
  return best;
}

struct Row {
  std::string technology;
  std::function<std::unique_ptr<ElementKernel>()> make;
};

void table(const std::string& cell, ElementType type, bool ring, const Material& law,
           const std::vector<Row>& rows, int evaluations) {
  double full = 0.0;
  for (const Row& row : rows) {
    const double t = microseconds(*row.make(), law, type, ring, evaluations);
    if (full == 0.0) full = t;
    std::printf("| %s | %s | %.2f | %.2f |\n", cell.c_str(), row.technology.c_str(), t, t / full);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int evaluations = 20000;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--evaluations") && i + 1 < argc) evaluations = std::atoi(argv[++i]);
    if (!std::strcmp(argv[i], "--cell") && i + 1 < argc) only = argv[++i];
  }

  J2SmallStrain::Parameters j2;
  j2.youngModulus = TemperatureDependent(200.0);
  j2.poissonRatio = TemperatureDependent(0.3);
  j2.yieldStress = TemperatureDependent(0.2);
  j2.isotropicHardening = TemperatureDependent(20.0);
  const J2SmallStrain smallStrain(j2);
  SimoMiehe::Parameters sm;
  sm.youngModulus = 200.0;
  sm.poissonRatio = 0.3;
  sm.yieldStress = 2.0;
  sm.isotropicHardening = 20.0;
  const SimoMiehe finiteStrain(sm);

  std::printf("| cell | technology | us per evaluation | against full |\n|---|---|---|---|\n");
  for (const auto& [type, ring] :
       {std::pair{ElementType::Quad4, false}, std::pair{ElementType::Hex8, false},
        std::pair{ElementType::Quad4, true}}) {
    const std::string cell = ring ? "ring" : type == ElementType::Quad4 ? "quad4" : "hex8";
    if (!only.empty() && only != cell) continue;
    const std::string name = ring ? "quad4 ring" : cell;
    table(name + " small strain", type, ring, smallStrain,
          {{"full", [=] { return makeElementKernel(type, Kinematics::SmallStrain, -1, ring); }},
           {"b-bar", [=] { return std::make_unique<ProjectedDilatationKernel>(type, 0, ring); }}},
          evaluations);
    table(name + " finite strain", type, ring, finiteStrain,
          {{"full", [=] { return makeElementKernel(type, Kinematics::FiniteStrain, -1, ring); }},
           {"f-bar", [=] { return std::make_unique<FBarKernel>(type, ring); }},
           {"mixed-up", [=] { return std::make_unique<ProjectedJacobianKernel>(type, 0, ring); }}},
          evaluations);
  }
  return 0;
}
