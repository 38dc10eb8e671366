// 1 rank and P ranks give the same displacements: every rank also solves the whole problem on
// its own (MPI_COMM_SELF) and compares node by node.
#include "ProblemTestSupport.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace contactlab::test {
namespace {

class Distributed : public ::testing::TestWithParam<std::string> {};

TEST_P(Distributed, SameDisplacementsAsOneRank) {
  const std::string type = GetParam();
  const int n = is3D(type) ? 3 : 6;
  auto mesh = unitMesh(type, n);
  distort(*mesh, n, type.rfind("tet", 0) == 0 ? 0.04 : 0.1);
  Field exact = [](const double* x, double* u) {
    u[0] = 0.01 * x[1] * x[1];
    u[1] = -0.02 * x[0] * x[1];
    u[2] = 0.01 * x[0] * x[2];
  };
  Field body = [](const double*, double* b) { b[0] = 1.0, b[1] = -2.0, b[2] = 0.5; };
  auto model = elasticModel(mesh, 1000.0, 0.3, exact, body);
  // Add a pressure on one face so that surface loads are covered too.
  model.dirichlet.pop_back();
  SurfaceLoad pressure;
  pressure.name = "p";
  pressure.group = boundaryGroups(mesh->dim).back();
  pressure.pressure = 3.0;
  model.surfaceLoads.push_back(pressure);

  auto comm = Tpetra::getDefaultComm();
  Problem distributed(model, comm);
  auto solver = makeSolver("mumps", comm);
  auto u = solve(distributed, *solver);

  Problem serial(model, selfComm());
  auto serialSolver = makeSolver("mumps", selfComm());
  auto us = solve(serial, *serialSolver);

  double maxDiff = 0, maxValue = 0;
  for (std::size_t node = 0; node < mesh->numNodes(); ++node) {
    if (serial.dofs().nodeOwner(node) < 0) continue;
    const auto a = distributed.nodeDisplacement(*u, node);
    const auto b = serial.nodeDisplacement(*us, node);
    for (int c = 0; c < mesh->dim; ++c) {
      maxDiff = std::max(maxDiff, std::fabs(a[c] - b[c]));
      maxValue = std::max(maxValue, std::fabs(b[c]));
    }
  }
  EXPECT_GT(maxValue, 0.0);
  EXPECT_LE(maxDiff, 1e-10 * maxValue) << type;
  // The reactions agree too.
  for (std::size_t r = 0; r < serial.reactions().size(); ++r)
    for (int c = 0; c < mesh->dim; ++c)
      EXPECT_NEAR(distributed.reactions()[r].force[c], serial.reactions()[r].force[c],
                  1e-9 * (1 + std::fabs(serial.reactions()[r].force[c])));
}

INSTANTIATE_TEST_SUITE_P(SomeElements, Distributed,
                         ::testing::Values("tri6", "quad4", "quad8", "tet10", "hex8", "hex27"));

}  // namespace
}  // namespace contactlab::test
