// Manufactured solutions (doc/verification.md V7): u_i = sin(a_i . x), with the body force that
// makes it exact, on a sequence of meshes of every element type. The observed rates of the
// L2 error approach p + 1 and those of the energy (H1 seminorm) error approach p.
#include "ProblemTestSupport.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab::test {
namespace {

constexpr double kE = 100.0, kNu = 0.25;
constexpr double kA[3][3] = {{1.1, 0.7, 0.4}, {-0.6, 1.3, 0.5}, {0.8, -0.9, 1.2}};

double phase(int i, const double* x, int dim) {
  double s = 0;
  for (int j = 0; j < dim; ++j)
    s += kA[i][j] * x[j];
  return s;
}

struct Rates {
  double l2, energy;
};

Rates observedRates(const std::string& type, int n0, int levels,
                    const Teuchos::RCP<const Comm>& comm) {
  const int dim = is3D(type) ? 3 : 2;
  const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  Field exact = [dim](const double* x, double* u) {
    for (int i = 0; i < dim; ++i)
      u[i] = std::sin(phase(i, x, dim));
  };
  auto gradient = [dim](const double* x, double* g) {
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j)
        g[i * 3 + j] = kA[i][j] * std::cos(phase(i, x, dim));
  };
  // b = -(mu lap u + (lambda + mu) grad div u)
  Field body = [=](const double* x, double* b) {
    for (int k = 0; k < dim; ++k) {
      double norm2 = 0;
      for (int j = 0; j < dim; ++j)
        norm2 += kA[k][j] * kA[k][j];
      b[k] = mu * norm2 * std::sin(phase(k, x, dim));
      for (int i = 0; i < dim; ++i)
        b[k] += (lambda + mu) * kA[i][i] * kA[i][k] * std::sin(phase(i, x, dim));
    }
  };
  std::vector<double> h, l2, energy;
  for (int level = 0, n = n0; level < levels; ++level, n *= 2) {
    Problem problem(elasticModel(unitMesh(type, n), kE, kNu, exact, body), comm);
    auto solver = makeSolver("mumps", comm);
    auto u = solve(problem, *solver);
    const auto errors = problem.displacementErrors(*u, exact, gradient);
    h.push_back(1.0 / n);
    l2.push_back(errors.l2);
    energy.push_back(errors.energy);
  }
  const std::size_t k = h.size() - 1;
  const double ratio = std::log(h[k - 1] / h[k]);
  return {std::log(l2[k - 1] / l2[k]) / ratio, std::log(energy[k - 1] / energy[k]) / ratio};
}

struct Case {
  std::string type;
  int n0, levels;
};

class ManufacturedSolution : public ::testing::TestWithParam<Case> {};

TEST_P(ManufacturedSolution, ConvergesAtTheOptimalRates) {
  const Case c = GetParam();
  const int p = info(elementTypeFromName(c.type)).order;
  const Rates rates = observedRates(c.type, c.n0, c.levels, Tpetra::getDefaultComm());
  EXPECT_GT(rates.l2, p + 1 - 0.25) << c.type;
  EXPECT_LT(rates.l2, p + 1 + 0.4) << c.type;
  EXPECT_GT(rates.energy, p - 0.2) << c.type;
  EXPECT_LT(rates.energy, p + 0.4) << c.type;
  if (Tpetra::getDefaultComm()->getRank() == 0)
    std::printf("%-6s L2 rate %.3f  energy rate %.3f\n", c.type.c_str(), rates.l2, rates.energy);
}

INSTANTIATE_TEST_SUITE_P(EveryElement, ManufacturedSolution,
                         ::testing::Values(Case{"tri3", 8, 3}, Case{"tri6", 4, 3},
                                           Case{"quad4", 8, 3}, Case{"quad8", 4, 3},
                                           Case{"quad9", 4, 3}, Case{"tet4", 4, 3},
                                           Case{"tet10", 2, 3}, Case{"hex8", 4, 3},
                                           Case{"hex20", 2, 3}, Case{"hex27", 2, 3}),
                         [](const auto& info) { return info.param.type; });

}  // namespace
}  // namespace contactlab::test
