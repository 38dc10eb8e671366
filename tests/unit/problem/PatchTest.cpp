// Element patch test (doc/verification.md V7): on a distorted mesh, a linear displacement field
// imposed on the boundary is reproduced exactly inside, with the constant stress it implies,
// for every element type.
#include "ProblemTestSupport.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab::test {
namespace {

class PatchTest : public ::testing::TestWithParam<std::string> {};

TEST_P(PatchTest, LinearFieldIsExactOnDistortedMesh) {
  const std::string type = GetParam();
  const int n = is3D(type) ? 2 : 3;
  auto mesh = unitMesh(type, n);
  // Tets are a sixth of a cell: distort them less to keep them valid.
  distort(*mesh, n, type.rfind("tet", 0) == 0 ? 0.04 : 0.12);
  const double A[3][3] = {{1e-3, 2e-3, -1e-3}, {-3e-3, 2e-3, 1e-3}, {2e-3, 1e-3, 4e-3}};
  Field exact = [&](const double* x, double* u) {
    for (int i = 0; i < 3; ++i)
      u[i] = 0.01 * (i + 1) + A[i][0] * x[0] + A[i][1] * x[1] + A[i][2] * x[2];
  };
  auto comm = Tpetra::getDefaultComm();
  Problem problem(elasticModel(mesh, 200.0, 0.3, exact, {}), comm);
  auto solver = makeSolver("mumps", comm);
  auto u = solve(problem, *solver);

  double maxError = 0, maxValue = 0;
  for (std::size_t node = 0; node < mesh->numNodes(); ++node) {
    if (problem.dofs().nodeOwner(node) < 0) continue;
    const auto uh = problem.nodeDisplacement(*u, node);
    double ue[3] = {0, 0, 0};
    exact(&mesh->coords[3 * node], ue);
    for (int c = 0; c < mesh->dim; ++c) {
      maxError = std::max(maxError, std::fabs(uh[c] - ue[c]));
      maxValue = std::max(maxValue, std::fabs(ue[c]));
    }
  }
  EXPECT_LT(maxError, 1e-10 * maxValue) << type;

  // Constant stress: sigma = C eps with eps from A (plane strain in 2D).
  const double E = 200.0, nu = 0.3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const int d = mesh->dim;
  double eps[3][3] = {};
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j)
      eps[i][j] = 0.5 * (A[i][j] + A[j][i]);
  const double trace = eps[0][0] + eps[1][1] + eps[2][2];
  const double expected[6] = {lambda * trace + 2 * mu * eps[0][0],
                              lambda * trace + 2 * mu * eps[1][1],
                              lambda * trace + 2 * mu * eps[2][2],
                              2 * mu * eps[0][1],
                              2 * mu * eps[1][2],
                              2 * mu * eps[0][2]};
  const auto s = problem.nodeStress(*u, mesh->numNodes() / 2, 1.0);
  for (int k = 0; k < 6; ++k)
    EXPECT_NEAR(s[k], expected[k], 1e-9) << type << " component " << k;
}

INSTANTIATE_TEST_SUITE_P(EveryElement, PatchTest,
                         ::testing::Values("tri3", "tri6", "quad4", "quad8", "quad9", "tet4",
                                           "tet10", "hex8", "hex20", "hex27"));

}  // namespace
}  // namespace contactlab::test
